#include <algorithm>
#include <chrono>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>
#include <utility>

#include "scbt/filter/segment_filter.h"
#include "scbt/lines/exposure.h"
#include "scbt/lines/line_detector.h"
#include "scbt/tracker/frame_checks.h"
#include "scbt/tracker/stage_clock.h"
#include "scbt/tracker/tracker_impl.h"

namespace scbt {
namespace {

// The detector's own smoothing (px), as far as a step edge's gradient is concerned.
double own_smoothing(const TrackerOptions& options) {
  return std::max(options.detector.sigma, 0.5);
}

}  // namespace

Tracker::Tracker(const TrackerOptions& options)
    : Tracker(make_tracker(options, [] { return std::make_unique<FastCycleStage>(); })) {}
Tracker::Tracker(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Tracker::~Tracker() = default;
Tracker::Tracker(Tracker&&) noexcept = default;
Tracker& Tracker::operator=(Tracker&&) noexcept = default;

void Tracker::init(const cv::Mat& frame, const Polygon& polygon) { impl_->init(frame, polygon); }
Polygon Tracker::init_from_box(const cv::Mat& frame, const cv::Rect& box) {
  return impl_->init_from_box(frame, box);
}
TrackResult Tracker::track(const cv::Mat& frame) { return impl_->track(frame); }
bool Tracker::initialized() const { return impl_->initialized(); }
const Polygon& Tracker::boundary() const { return impl_->boundary(); }
const TrackerOptions& Tracker::options() const { return impl_->options(); }
void Tracker::set_keep_debug(bool keep) { impl_->set_keep_debug(keep); }
const TrackDebug& Tracker::debug() const { return impl_->debug(); }

const char* step_name(SearchStep step) {
  switch (step) {
    case SearchStep::kNone:
      return "none";
    case SearchStep::kPredicted:
      return "predicted";
    case SearchStep::kUnmoved:
      return "unmoved";
    case SearchStep::kGrowth:
      return "growth";
    case SearchStep::kSmaller:
      return "smaller";
    case SearchStep::kImageMotion:
      return "image motion";
    case SearchStep::kInPlace:
      return "in place";
    case SearchStep::kMemory:
      return "memory";
    case SearchStep::kWholeFrame:
      return "whole frame";
  }
  return "none";
}

Tracker make_tracker(const TrackerOptions& options, const MakeCycleStage& make_cycle_stage) {
  return Tracker(std::make_unique<Tracker::Impl>(options, make_cycle_stage));
}

Tracker::Impl::Impl(const TrackerOptions& options, const MakeCycleStage& make_cycle_stage)
    : options_(options),
      appearance_(options.appearance),
      monitor_(options.loss),
      view_change_(options.loss.view_change),
      memory_(options.memory) {
  options_.check();
  detector_ = make_line_detector(options_.detector);
  gradient_threshold_ = options_.detector.gradient_threshold;
  anchor_threshold_ = options_.detector.anchor_threshold;
  step_threshold_ = gradient_threshold_;
  for (Attempt& a : attempts_) a.cycles = make_cycle_stage();
}

void Tracker::Impl::scale_thresholds_to_exposure(const cv::Mat& frame) {
  gradient_threshold_ = options_.detector.gradient_threshold;
  anchor_threshold_ = options_.detector.anchor_threshold;
  exposure_stretch_ = {};
  if (options_.exposure.normalize && detector_->adapts_thresholds()) {
    IntensityLevels levels;
    const double spread = intensity_spread(frame, options_.exposure.sample_step, &levels);
    exposure_stretch_ = grey_stretch(exposure_gain(spread, options_.exposure), levels);
    gradient_threshold_ = threshold_for_exposure(gradient_threshold_, exposure_stretch_.residual);
    anchor_threshold_ = threshold_for_exposure(anchor_threshold_, exposure_stretch_.residual);
  }
  step_threshold_ = gradient_threshold_;
  const double blur_gain = edge_blur_gain(edge_blur_sigma_, own_smoothing(options_), options_.blur);
  if (options_.blur.adapt && detector_->adapts_thresholds() && blur_gain < 1.0) {
    gradient_threshold_ =
        std::max(1, static_cast<int>(std::lround(gradient_threshold_ * blur_gain)));
    const double anchor_gain =
        edge_blur_anchor_gain(edge_blur_sigma_, own_smoothing(options_), options_.blur);
    anchor_threshold_ = std::max(1, static_cast<int>(std::lround(anchor_threshold_ * anchor_gain)));
  }
  detector_->set_edge_thresholds(gradient_threshold_, anchor_threshold_);
}

void Tracker::Impl::to_exposed_gray(const cv::Mat& part, cv::Mat* gray) const {
  to_gray(part, gray);  // a buffer of the tracker's own, never the caller's frame
  if (exposure_stretch_.gain <= 1.0) return;
  apply_grey_stretch(exposure_stretch_, gray);
}

void Tracker::Impl::measure_edge_blur(const cv::Mat& gray, cv::Point window_tl) {
  blur_frames_waited_ = 0;
  if (!options_.blur.adapt) return;
  // A clear step: twice the smallest one the detector sees (a Sobel response of the threshold is
  // a step of about a quarter of it).
  const double sigma =
      estimate_edge_blur(gray, window_tl, boundary_, step_threshold_ / 2.0, options_.blur);
  if (!(sigma > 0.0)) return;
  // A camera's blur changes over frames; one frame's estimate is noisy.
  const double weight =
      1.0 - std::pow(1.0 - options_.blur.update_weight, options_.blur.measure_every);
  edge_blur_sigma_ =
      edge_blur_sigma_ > 0.0 ? edge_blur_sigma_ + weight * (sigma - edge_blur_sigma_) : sigma;
}

void Tracker::Impl::init(const cv::Mat& frame, const Polygon& polygon) {
  check_tracker_init(frame, polygon, &gray_);
  boundary_ = polygon;
  boundary_area_ = area(polygon);
  reference_roi_ = cv::Rect(cv::Point(0, 0), frame.size());
  edge_blur_sigma_ = -1.0;
  scale_thresholds_to_exposure(frame);  // the exposure's stretch is what the blur estimate needs
  to_exposed_gray(frame, &reference_gray_);
  measure_edge_blur(reference_gray_, cv::Point(0, 0));
  scale_thresholds_to_exposure(frame);
  frame_size_ = frame.size();
  motion_.reset();
  motion_.update(boundary_);
  adapted_first_ = false;
  noise_sigma_ = -1.0;
  appearance_pending_ = false;
  appearance_.remember(frame, boundary_);
  shape_memory_.restart(boundary_);
  memory_.clear();
  former_memory_.clear();
  memory_provisional_ = 0;
  new_view_frames_ = 0;
  frames_since_stand_in_ = kPartlySeenHold + 1;
  if (options_.object_memory) memory_.restart(boundary_, reference_gray_, {0, 0});
  monitor_.reset(
      polygon, unstretched_level(exposure_stretch_,
                                 sample_edges(polygon, reference_gray_, {0, 0}, 0.0).inside_level));
  pending_.clear();
  last_partly_seen_ = MemoryFit();
  pending_matches_ = 0;
  keyframes_.clear();
}

void Tracker::Impl::attempt(const cv::Mat& frame, const Polygon& prior, Attempt* a,
                            double min_similarity, bool adapt, double gate_area) {
  a->num_dropped = 0;
  a->choice.reset();
  a->assessed = false;
  const Clock::time_point line_start = Clock::now();
  // Only segments near the prior boundary can survive the distance filter, so only the window
  // around it is converted and searched (crop_to_boundary; whole frame otherwise).
  a->roi = cv::Rect(cv::Point(0, 0), frame_size_);
  if (options_.detector.crop_to_boundary) {
    a->roi =
        detection_roi(prior, options_.filter_distance + options_.detector.roi_padding, frame_size_);
    if (a->roi.empty()) a->roi = cv::Rect(cv::Point(0, 0), frame_size_);
  }
  to_exposed_gray(frame(a->roi), &gray_);
  gray_roi_ = a->roi;
  const cv::Mat* detect_on = &gray_;
  bool thresholds_changed = adapt;
  if (adapt) {
    // Thresholds (and smoothing) for this window only
    // (AdaptiveThresholdOptions::retry_weak_frames).
    AdaptiveThresholdOptions this_window = options_.adaptive_thresholds;
    this_window.enabled = true;
    detect_on = &adapt_to_frame(gray_, a->roi.tl(), prior, gradient_threshold_, anchor_threshold_,
                                this_window, &smoothed_gray_, &a->thresholds, camera_noise(gray_));
    detector_->set_edge_thresholds(a->thresholds.gradient, a->thresholds.anchor);
  } else if (options_.smooth_noisy_frames && !options_.adaptive_thresholds.enabled &&
             detector_->adapts_thresholds()) {
    detect_on = &smooth_if_noisy(gray_, &smoothed_gray_, &thresholds_changed);
  } else if (options_.adaptive_thresholds.enabled && detector_->adapts_thresholds()) {
    // Thresholds (and, for a noisy window, a smoothed copy to detect on) suited to this window.
    detect_on = &adapt_to_frame(gray_, a->roi.tl(), prior, gradient_threshold_, anchor_threshold_,
                                options_.adaptive_thresholds, &smoothed_gray_, &a->thresholds);
    detector_->set_edge_thresholds(a->thresholds.gradient, a->thresholds.anchor);
  }
  if (options_.detector.crop_to_boundary) {
    // Detectors that can (edlines) look only at the band around the prior boundary.
    a->detected = detector_->detect_near(*detect_on, a->roi.tl(), frame_size_, prior,
                                         options_.filter_distance + options_.detector.roi_padding);
  } else {
    a->detected = detector_->detect_in(*detect_on, a->roi.tl(), frame_size_);
  }
  if (thresholds_changed) {
    detector_->set_edge_thresholds(gradient_threshold_, anchor_threshold_);
  }
  a->line_ms = elapsed_ms(line_start);

  Clock::time_point stage_start = Clock::now();
  // Ends the stage that began at stage_start, returning its time, and starts the next.
  auto lap = [&stage_start]() {
    const Clock::time_point now = Clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - stage_start).count();
    stage_start = now;
    return ms;
  };
  filter_segments_near_boundary(a->detected, prior, options_.filter_distance, &a->kept,
                                &a->kept_distances);
  if (static_cast<int>(a->kept.size()) > options_.max_segments) {
    a->num_dropped = static_cast<int>(a->kept.size()) - options_.max_segments;
    std::nth_element(a->kept.begin(), a->kept.begin() + options_.max_segments, a->kept.end(),
                     [](const Segment& l, const Segment& r) { return l.length() > r.length(); });
    a->kept.resize(options_.max_segments);
  }
  a->stages.filter_ms = lap();
  build_segment_graph(a->kept, &a->graph);
  a->stages.graph_ms = lap();
  a->cycles->search(a->graph, options_.bdsp);
  a->stages.search_ms = lap();
  // The choice asks for the distances of the graph's points to `prior`; the filter computed
  // them for the kept segments (unless the cap reordered them).
  KnownSegmentDistances known{&a->kept, &a->kept_distances};
  const KnownSegmentDistances* known_if_any = a->num_dropped == 0 ? &known : nullptr;
  // Not while lost: an object found again may be nearer or farther than when it was lost.
  RankingWeights weights;
  if (monitor_.state() != TrackState::kLost) {
    weights = {options_.similarity_exponent, options_.shape_weight, &shape_memory_.descriptor()};
  }
  a->choice = a->cycles->choose(&chooser_, a->graph, prior, min_similarity, options_.cost_tolerance,
                                known_if_any, gate_area, weights);
  a->stages.choice_ms = lap();
  a->grouping_ms =
      a->stages.filter_ms + a->stages.graph_ms + a->stages.search_ms + a->stages.choice_ms;
}

double Tracker::Impl::camera_noise(const cv::Mat& gray) {
  // A camera's noise changes slowly: measured on the first window of every kNoiseInterval-th
  // frame that asks.
  constexpr int kNoiseInterval = 8;
  if (noise_sigma_ < 0.0 || frames_since_noise_estimate_ >= kNoiseInterval) {
    noise_sigma_ = estimate_noise_sigma(gray, 4);
    frames_since_noise_estimate_ = 0;
  }
  return noise_sigma_;
}

const cv::Mat& Tracker::Impl::smooth_if_noisy(const cv::Mat& gray, cv::Mat* smoothed,
                                              bool* thresholds_changed) {
  const double sigma = smoothing_for_noise(camera_noise(gray), options_.adaptive_thresholds);
  if (sigma <= 0.0) return gray;
  cv::GaussianBlur(gray, *smoothed, cv::Size(0, 0), sigma);
  // A step edge's steepest gradient falls with the total smoothing, noise's much faster: the
  // thresholds fall with the step's, so that an edge the published ones find is still found.
  const double own = own_smoothing(options_);
  const double step_gain = own / std::sqrt(own * own + sigma * sigma);
  detector_->set_edge_thresholds(
      std::max(1, static_cast<int>(std::lround(gradient_threshold_ * step_gain))),
      std::max(1, static_cast<int>(std::lround(anchor_threshold_ * step_gain))));
  *thresholds_changed = true;
  return *smoothed;
}

bool Tracker::Impl::keeps_motion_reference() const {
  return options_.recover_by_motion || (options_.predict_motion && options_.measure_motion);
}

void Tracker::Impl::remember_reference(const Attempt& a) {
  // The reference is the window the image motion is measured against (recovery, prediction).
  if (!keeps_motion_reference()) return;
  settle_appearance();
  reference_roi_ = a.roi;
  // gray_ holds its own conversion (to_gray): hand it over instead of copying it; the next
  // frame's conversion then reuses the old reference's buffer.
  std::swap(gray_, reference_gray_);
}

void Tracker::Impl::report_attempt(const Attempt& a, TrackResult* result) {
  result->num_detected = static_cast<int>(a.detected.size());
  result->num_kept = static_cast<int>(a.kept.size());
  result->num_dropped = a.num_dropped;
  result->num_vertices = a.graph.num_vertices();
  result->num_edges = a.graph.num_edges();
  result->num_candidates = a.cycles->num_candidates();
  if (keep_debug_) {
    debug_.detected = a.detected;
    debug_.graph = a.graph;
  }
}

TrackResult Tracker::Impl::track(const cv::Mat& frame) {
  if (!initialized()) throw std::logic_error("Tracker::track called before init");
  if (frame.empty()) to_gray(frame, &gray_);  // throws
  check_frame_size(frame, frame_size_);
  scale_thresholds_to_exposure(frame);
  ++frames_since_noise_estimate_;
  if (monitor_.state() == TrackState::kLost) return track_lost(frame);
  TrackResult result;
  Attempt* a = search(frame, &result);

  MemoryCheck memory;
  if (options_.object_memory && memory_.ready()) {
    memory = check_with_memory(frame, a);
    result.visible = memory.fit.valid ? memory.fit.visible : 0.0;
  }
  const MemoryFit& fit = memory.fit;
  const MemoryVerdict verdict = memory.verdict;
  frames_since_stand_in_ = verdict == MemoryVerdict::kStandsIn
                               ? 0
                               : std::min(frames_since_stand_in_ + 1, kPartlySeenHold + 1);
  if (verdict == MemoryVerdict::kStandsIn) {
    // The remembered outline where the visible part of the object puts it. The loss monitor
    // learns nothing from it but that the object is there, partly hidden; the state says how much
    // is seen.
    monitor_.note_partly_seen();
    boundary_ = fit.outline;
    boundary_area_ = area(boundary_);
    report_memory_fit(fit, &result);
    result.state =
        fit.visible >= options_.min_visible ? TrackState::kTracking : TrackState::kUncertain;
    motion_.update(boundary_);
    result.boundary = boundary_;
    report_attempt(*a, &result);
    return result;
  }
  bool departs = false;
  if (a->choice) {
    // Before the grey window is handed to the motion reference, and against the previous boundary.
    if (!a->assessed) assess(a, boundary_);
    // Before a confident cycle moves the memory.
    departs = departs_after_stand_in(memory, *a);
    result.evidence = a->evidence;
    result.confidence = a->confidence;
    check_view_cut(frame, result);  // before the motion reference moves on
    boundary_ = std::move(a->boundary);
    boundary_area_ = a->cycles->area(a->choice->index);
    result.cost = a->choice->cost;
    result.area_similarity = a->choice->similarity;
    // Before the motion reference takes the grey window (the chosen attempt's).
    if (result.confidence >= options_.loss.tracking_confidence && gray_roi_ == a->roi &&
        ++blur_frames_waited_ >= options_.blur.measure_every) {
      measure_edge_blur(gray_, a->roi.tl());
    }
    if (options_.object_memory && result.confidence >= options_.loss.tracking_confidence &&
        gray_roi_ == a->roi) {
      learn_from_cycle(memory, a->roi.tl());
    }
    // This frame's appearance replaces a pending one, which need not be read first.
    if (options_.predict_motion && options_.confirm_motion) appearance_pending_ = false;
    remember_reference(*a);
    motion_.update(boundary_);
    remember_appearance(frame);
  } else {
    result.held = true;
    result.visible = 0.0;
    check_view_cut(frame, result);
    motion_.update_held();
  }
  // A cycle along the memory's fitted outline, with as much of the object seen as a stand-in is
  // `tracking` with, is the remembered object, whatever the stale shape before an occluder says.
  const bool vouched = verdict == MemoryVerdict::kAgrees && fit.visible >= options_.min_visible;
  // A found boundary's descriptor came with its evidence (assess): the monitor needs no other.
  result.state = monitor_.update(boundary_, result.confidence, result.held, result.evidence,
                                 result.held ? nullptr : &a->descriptor,
                                 result.recovered || result.step == SearchStep::kSmaller, vouched);
  if (result.state == TrackState::kTracking) {
    keyframes_.offer(frame, boundary_);
    if (options_.shape_weight > 0.0) shape_memory_.remember(boundary_);
  }
  if (result.state == TrackState::kLost && !result.held) {
    // Lost on a boundary found but not trusted: back to the newest confident one. Lost on a held
    // frame, the held boundary stays (the last found, nearest to where the object went).
    boundary_ = monitor_.latest_confident();
    boundary_area_ = area(boundary_);
    result.step = SearchStep::kNone;  // the boundary reported is no step's
  }
  if (result.state == TrackState::kLost) lost_output_ = boundary_;
  if (departs && result.state != TrackState::kLost) doubt_departure_from_memory(&result);

  result.boundary = boundary_;
  report_attempt(*a, &result);
  return result;
}

}  // namespace scbt
