#include "scbt/tracker/track_state.h"

#include <algorithm>
#include <cmath>
#include <limits>
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

void LossMonitor::add_confident(const Polygon& boundary, double inside_level, double confidence,
                                const ShapeDescriptor* descriptor) {
  const int slot = kept_next_;
  Confident& added = kept_[slot];
  added.boundary = boundary;  // reuses the slot's buffer
  added.descriptor = descriptor != nullptr ? *descriptor : shape_descriptor(boundary);
  // An unknown level keeps the last known one.
  added.level = inside_level >= 0.0 ? inside_level : last_confident_.level;
  added.confidence = confidence;
  kept_next_ = (kept_next_ + 1) % kKept;
  kept_size_ = std::min(kept_size_ + 1, kKept);
  // An invalid descriptor is infinitely far from any other: capped, so the sums stay comparable.
  constexpr double kFar = 1.0;
  for (int j = 0; j < kKept; ++j) {
    distance_[slot][j] = distance_[j][slot] =
        std::min(shape_distance(added.descriptor, kept_[j].descriptor), kFar);
  }
  // The weighted medoid; ties go to the newest (the kept frames are visited newest first).
  int best = slot;
  double best_sum = std::numeric_limits<double>::infinity();
  for (int n = 0; n < kept_size_; ++n) {
    const int i = (slot + kKept - n) % kKept;
    double sum = 0.0;
    for (int m = 0; m < kept_size_; ++m) {
      const int j = (slot + kKept - m) % kKept;
      sum += kept_[j].confidence * distance_[i][j];
    }
    if (sum < best_sum) {
      best_sum = sum;
      best = i;
    }
  }
  last_confident_ = kept_[best];
  // What a loss kLag frames later will search for: this frame's own shape (the freshest: an
  // object turns while out of sight), unless it is an outlier of the frames around it.
  past_references_[past_next_] =
      distance_[slot][best] <= options_.match_shape_distance ? added : last_confident_;
  past_next_ = (past_next_ + 1) % kLag;
  past_size_ = std::min(past_size_ + 1, kLag);
}

void LossMonitor::reset(const Polygon& boundary, double inside_level) {
  last_confident_.level = -1.0;
  kept_size_ = 0;
  kept_next_ = 0;
  past_size_ = 0;
  past_next_ = 0;
  add_confident(boundary, inside_level, 1.0);
  state_ = TrackState::kTracking;
  misses_ = 0;
  unsure_ = 0;
  after_cut_ = false;
}

bool LossMonitor::keeps_level(const BoundaryEvidence& evidence) const {
  const double level = last_confident_.level;
  return level < 0.0 || evidence.inside_level < 0.0 ||
         std::abs(evidence.inside_level - level) <= options_.max_level_change;
}

bool LossMonitor::matches(const Polygon& cycle, const BoundaryEvidence& evidence, double confidence,
                          double min_confidence) const {
  if (confidence < min_confidence || !keeps_level(evidence)) return false;
  return shape_distance(shape_descriptor(cycle), last_confident_.descriptor) <=
         options_.match_shape_distance;
}

TrackState LossMonitor::update(const Polygon& boundary, double confidence, bool held,
                               const BoundaryEvidence& evidence, const ShapeDescriptor* descriptor,
                               bool refound, bool vouched) {
  const bool miss = held || confidence < options_.miss_confidence;
  // A boundary found after a cut of the view, or away from where it was searched for, is a
  // re-find: it must keep the last confident shape and inside level, as one found while lost
  // (unless the object memory vouches for it).
  const bool must_match = (after_cut_ || refound) && !vouched;
  const bool confident = confidence >= options_.tracking_confidence &&
                         (!must_match || (evidence.shape_change <= options_.match_shape_distance &&
                                          keeps_level(evidence)));
  unsure_ = confident ? 0 : unsure_ + 1;
  if (miss || unsure_ >= options_.unsure_to_lost) {
    misses_ += miss ? 1 : 0;
    const bool lost = options_.enabled &&
                      (misses_ >= options_.misses_to_lost || unsure_ >= options_.unsure_to_lost);
    if (lost && state_ != TrackState::kLost) {
      last_confident_ = past_references_[(past_next_ + kLag - past_size_) % kLag];
    }
    state_ = lost ? TrackState::kLost : TrackState::kUncertain;
    return state_;
  }
  misses_ = 0;
  if (confident) {
    after_cut_ = false;
    add_confident(boundary, evidence.inside_level, confidence, descriptor);
    state_ = TrackState::kTracking;
  } else {
    state_ = TrackState::kUncertain;
  }
  return state_;
}

}  // namespace scbt
