#include "scbt/tracker/track_state.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace scbt {

std::string to_string(TrackState state) {
  switch (state) {
    case TrackState::kTracking:
      return "tracking";
    case TrackState::kUncertain:
      return "uncertain";
    case TrackState::kLost:
      return "lost";
  }
  return "unknown";
}

void LossOptions::check() const {
  if (!(tracking_confidence > 0.0 && tracking_confidence <= 1.0)) {
    throw std::invalid_argument("tracking_confidence must be in (0, 1], got " +
                                std::to_string(tracking_confidence));
  }
  if (!(miss_confidence >= 0.0 && miss_confidence <= tracking_confidence)) {
    throw std::invalid_argument("miss_confidence must be in [0, tracking_confidence], got " +
                                std::to_string(miss_confidence));
  }
  if (unsure_to_lost < 1 || unsure_to_lost > 1000) {
    throw std::invalid_argument("unsure_to_lost must be in 1..1000, got " +
                                std::to_string(unsure_to_lost));
  }
  if (misses_to_lost < 1 || misses_to_lost > 1000) {
    throw std::invalid_argument("misses_to_lost must be in 1..1000, got " +
                                std::to_string(misses_to_lost));
  }
  if (!(reacquire_confidence >= tracking_confidence && reacquire_confidence <= 1.0)) {
    throw std::invalid_argument("reacquire_confidence must be in [tracking_confidence, 1], got " +
                                std::to_string(reacquire_confidence));
  }
  if (!(match_shape_distance > 0.0 && match_shape_distance <= 1.0)) {
    throw std::invalid_argument("match_shape_distance must be in (0, 1], got " +
                                std::to_string(match_shape_distance));
  }
  if (!(min_scale > 0.1 && min_scale <= 1.0 && max_scale >= 1.0 && max_scale < 10.0)) {
    throw std::invalid_argument("scales must satisfy 0.1 < min_scale <= 1 <= max_scale < 10, got " +
                                std::to_string(min_scale) + " and " + std::to_string(max_scale));
  }
  if (!(max_level_change > 0.0 && max_level_change <= 255.0)) {
    throw std::invalid_argument("max_level_change must be in (0, 255], got " +
                                std::to_string(max_level_change));
  }
  if (!(cut_correlation >= -1.0 && cut_correlation <= 1.0)) {
    throw std::invalid_argument("cut_correlation must be in [-1, 1], got " +
                                std::to_string(cut_correlation));
  }
  if (confirm_frames < 1 || confirm_frames > 100) {
    throw std::invalid_argument("confirm_frames must be in 1..100, got " +
                                std::to_string(confirm_frames));
  }
  if (near_tries < 0 || frame_tries < 0 || near_tries + frame_tries < 1 || near_tries > 100 ||
      frame_tries > 100) {
    throw std::invalid_argument("near_tries and frame_tries must be in 0..100, not both 0");
  }
  view_change.check();
}

void LossMonitor::set_confident(const Polygon& boundary, double inside_level) {
  last_confident_ = boundary;
  reference_ = shape_descriptor(boundary);
  if (inside_level >= 0.0) reference_level_ = inside_level;
  Confident& slot = history_[history_next_];
  slot.boundary = boundary;  // reuses the slot's buffer
  slot.descriptor = reference_;
  slot.level = reference_level_;
  history_next_ = (history_next_ + 1) % kHistory;
  history_size_ = std::min(history_size_ + 1, kHistory);
}

void LossMonitor::reset(const Polygon& boundary, double inside_level) {
  reference_level_ = -1.0;
  history_size_ = 0;
  history_next_ = 0;
  set_confident(boundary, inside_level);
  state_ = TrackState::kTracking;
  misses_ = 0;
  unsure_ = 0;
  after_cut_ = false;
}

bool LossMonitor::matches(const Polygon& cycle, const BoundaryEvidence& evidence, double confidence,
                          double min_confidence) const {
  if (confidence < min_confidence) return false;
  if (reference_level_ >= 0.0 && evidence.inside_level >= 0.0 &&
      std::abs(evidence.inside_level - reference_level_) > options_.max_level_change) {
    return false;
  }
  return shape_distance(shape_descriptor(cycle), reference_) <= options_.match_shape_distance;
}

TrackState LossMonitor::update(const Polygon& boundary, double confidence, bool held,
                               const BoundaryEvidence& evidence) {
  const bool miss = held || confidence < options_.miss_confidence;
  const bool confident = confidence >= options_.tracking_confidence &&
                         (!after_cut_ || evidence.shape_change <= options_.match_shape_distance);
  unsure_ = confident ? 0 : unsure_ + 1;
  if (miss || unsure_ >= options_.unsure_to_lost) {
    misses_ += miss ? 1 : 0;
    const bool lost = options_.enabled &&
                      (misses_ >= options_.misses_to_lost || unsure_ >= options_.unsure_to_lost);
    if (lost && state_ != TrackState::kLost && history_size_ > 0) {
      const Confident& oldest = history_[(history_next_ + kHistory - history_size_) % kHistory];
      last_confident_ = oldest.boundary;
      reference_ = oldest.descriptor;
      reference_level_ = oldest.level;
    }
    state_ = lost ? TrackState::kLost : TrackState::kUncertain;
    return state_;
  }
  misses_ = 0;
  if (confident) {
    after_cut_ = false;
    set_confident(boundary, evidence.inside_level);
    state_ = TrackState::kTracking;
  } else {
    state_ = TrackState::kUncertain;
  }
  return state_;
}

}  // namespace scbt
