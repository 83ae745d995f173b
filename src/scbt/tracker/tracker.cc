#include "scbt/tracker/tracker.h"

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
#include "scbt/tracker/motion_estimate.h"

namespace scbt {
namespace {

using Clock = std::chrono::steady_clock;

double elapsed_ms(Clock::time_point since) {
  return std::chrono::duration<double, std::milli>(Clock::now() - since).count();
}

// The detector's own smoothing (px), as far as a step edge's gradient is concerned.
double own_smoothing(const TrackerOptions& options) {
  return std::max(options.detector.sigma, 0.5);
}

}  // namespace

void Tracker::add_retry_times(const Attempt& retry, TrackResult* result) {
  result->line_ms += retry.line_ms;
  result->grouping_ms += retry.grouping_ms;
  result->stages.filter_ms += retry.stages.filter_ms;
  result->stages.graph_ms += retry.stages.graph_ms;
  result->stages.search_ms += retry.stages.search_ms;
  result->stages.choice_ms += retry.stages.choice_ms;
}

Tracker::Tracker(const TrackerOptions& options)
    : Tracker(options, [] { return std::make_unique<FastCycleStage>(); }) {}

Tracker::Tracker(const TrackerOptions& options,
                 const std::function<std::unique_ptr<CycleStage>()>& make_cycle_stage)
    : options_(options),
      appearance_(options.appearance),
      monitor_(options.loss),
      view_change_(options.loss.view_change) {
  options_.check();
  detector_ = make_line_detector(options_.detector);
  gradient_threshold_ = options_.detector.gradient_threshold;
  anchor_threshold_ = options_.detector.anchor_threshold;
  step_threshold_ = gradient_threshold_;
  for (Attempt& a : attempts_) a.cycles = make_cycle_stage();
}

Tracker::~Tracker() = default;
Tracker::Tracker(Tracker&&) noexcept = default;
Tracker& Tracker::operator=(Tracker&&) noexcept = default;

void Tracker::scale_thresholds_to_exposure(const cv::Mat& frame) {
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

void Tracker::to_exposed_gray(const cv::Mat& part, cv::Mat* gray) const {
  to_gray(part, gray);
  if (exposure_stretch_.gain <= 1.0) return;
  // Grey input comes back as a view of the caller's frame, which must not be written.
  if (gray->data == part.data) *gray = gray->clone();
  apply_grey_stretch(exposure_stretch_, gray);
}

void Tracker::measure_edge_blur(const cv::Mat& gray, cv::Point window_tl) {
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

void Tracker::init(const cv::Mat& frame, const Polygon& polygon) {
  check_tracker_init(frame, polygon, &gray_);
  boundary_ = polygon;
  boundary_area_ = area(polygon);
  reference_roi_ = cv::Rect(cv::Point(0, 0), frame.size());
  edge_blur_sigma_ = -1.0;
  scale_thresholds_to_exposure(frame);  // the exposure's stretch is what the blur estimate needs
  to_exposed_gray(frame, &reference_gray_);
  reference_gray_ = reference_gray_.clone();
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
  monitor_.reset(
      polygon, unstretched_level(exposure_stretch_,
                                 sample_edges(polygon, reference_gray_, {0, 0}, 0.0).inside_level));
  pending_.clear();
  pending_matches_ = 0;
  keyframes_.clear();
}

void Tracker::attempt(const cv::Mat& frame, const Polygon& prior, Attempt* a, double min_similarity,
                      bool adapt, double gate_area) {
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

double Tracker::camera_noise(const cv::Mat& gray) {
  // A camera's noise changes slowly: measured on the first window of every kNoiseInterval-th
  // frame that asks.
  constexpr int kNoiseInterval = 8;
  if (noise_sigma_ < 0.0 || frames_since_noise_estimate_ >= kNoiseInterval) {
    noise_sigma_ = estimate_noise_sigma(gray, 4);
    frames_since_noise_estimate_ = 0;
  }
  return noise_sigma_;
}

const cv::Mat& Tracker::smooth_if_noisy(const cv::Mat& gray, cv::Mat* smoothed,
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

bool Tracker::keeps_motion_reference() const {
  return options_.recover_by_motion || (options_.predict_motion && options_.measure_motion);
}

void Tracker::remember_reference(const cv::Mat& frame, const Attempt& a) {
  // The reference is the window the image motion is measured against (recovery, prediction).
  if (!keeps_motion_reference()) return;
  settle_appearance();
  reference_roi_ = a.roi;
  if (frame.channels() == 1) {
    // Grey input is a view of the caller's frame: a deep copy, into the reused buffer.
    gray_.copyTo(reference_gray_);
  } else {
    // gray_ holds its own conversion: hand it over instead of copying it; the next frame's
    // conversion then reuses the old reference's buffer.
    std::swap(gray_, reference_gray_);
  }
}

void Tracker::report_attempt(const Attempt& a, TrackResult* result) {
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

void Tracker::remember_appearance(const cv::Mat& frame) {
  if (!options_.predict_motion || !options_.confirm_motion) return;
  appearance_pending_ = false;
  if (keeps_motion_reference() && !reference_gray_.empty()) {
    appearance_boundary_ = boundary_;
    appearance_pending_ = true;
  } else {
    appearance_.remember(frame, boundary_);
  }
}

void Tracker::settle_appearance() {
  if (!appearance_pending_) return;
  appearance_pending_ = false;
  // The reference window holds the boundary with the profile's few pixels either side (it is
  // the search band's), unless the frame's edge cuts both alike.
  for (Point& p : appearance_boundary_) p -= Point(reference_roi_.x, reference_roi_.y);
  appearance_.remember(reference_gray_, appearance_boundary_);
}

bool Tracker::confirmed(const cv::Mat& frame, const Polygon& moved, const Polygon& unmoved) {
  settle_appearance();
  const double agreement = appearance_.agreement(frame, moved);
  return agreement >= options_.min_motion_agreement &&
         agreement > appearance_.agreement(frame, unmoved);
}

Tracker::Attempt* Tracker::search(const cv::Mat& frame, TrackResult* result) {
  found_smaller_ = false;
  if (options_.predict_motion && options_.measure_motion) {
    place_by_image_motion(frame);
  } else if (options_.predict_motion) {
    motion_.predict(boundary_, /*with_scale=*/false, &predicted_);
    if (options_.confirm_motion && predicted_ != boundary_ &&
        !confirmed(frame, predicted_, boundary_)) {
      predicted_ = boundary_;
    }
  } else {
    predicted_ = boundary_;
  }
  // At a low frame rate an object receding steadily shrinks by more than the gate between frames.
  // The gate then compares with the shrunken area; never with a grown one, since Γ already favours
  // larger cycles and a cycle creeping outward grows steadily too.
  const double gate_area = options_.predict_motion && options_.gate_sustained_shrink &&
                                   monitor_.state() != TrackState::kLost
                               ? boundary_area_ * motion_.sustained_shrink_ratio()
                               : 0.0;
  // Not while lost: the search there (tracker_resume.cc) asks for the last confident shape, which
  // the published thresholds found; lowered ones invite a different cycle in its place.
  const bool retry_weak_frames =
      options_.adaptive_thresholds.retry_weak_frames && !options_.adaptive_thresholds.enabled &&
      detector_->adapts_thresholds() && monitor_.state() != TrackState::kLost;
  const bool adapted_first = retry_weak_frames && adapted_first_;
  Attempt* a = &attempts_[0];
  attempt(frame, predicted_, a, options_.min_area_similarity, adapted_first, gate_area);
  result->line_ms = a->line_ms;
  result->grouping_ms = a->grouping_ms;
  result->stages = a->stages;
  if (retry_weak_frames) a = retry_weak(frame, a, predicted_, &attempts_[1], result, gate_area);

  // A prediction can be wrong (a blurred frame's measured motion, a camera that stopped): when
  // nothing trusted was found where it points, where the boundary was is searched as well.
  if (options_.fall_back_unmoved && predicted_ != boundary_) {
    if (!a->assessed) assess(a, boundary_);
    if (!trusted(*a, /*adapted=*/false)) {
      const bool adapted_before = adapted_first_;
      adapted_first_ = adapted_first;
      Attempt* unmoved = &attempts_[2];
      attempt(frame, boundary_, unmoved, options_.min_area_similarity, adapted_first, gate_area);
      add_retry_times(*unmoved, result);
      if (retry_weak_frames) {
        unmoved = retry_weak(frame, unmoved, boundary_, &attempts_[3], result, gate_area);
      }
      if (!unmoved->assessed) assess(unmoved, boundary_);
      // A second search tests more cycles: its boundary must also keep the reference shape.
      if (trusted(*unmoved, /*adapted=*/true)) {
        a = unmoved;
      } else {
        adapted_first_ = adapted_before;
      }
      // The grey window must be the chosen attempt's (the motion reference is taken from it).
      if (a->roi != gray_roi_) {
        to_exposed_gray(frame(a->roi), &gray_);
        gray_roi_ = a->roi;
      }
    }
  }

  // No candidate within the area gate of the last boundary: at a low frame rate an object
  // approaching or receding fast grows or shrinks by more than the gate between frames. Search
  // again with the size its recent growth predicts (if the image confirms that size: a growth
  // measured on a mis-tracked frame would otherwise compound).
  if (!a->choice && options_.predict_motion &&
      !(area_similarity(motion_.predicted_area_ratio(), 1.0) > options_.min_area_similarity)) {
    Polygon scaled;
    motion_.predict(boundary_, /*with_scale=*/true, &scaled);
    if (!options_.confirm_motion || confirmed(frame, scaled, predicted_)) {
      Attempt* retry = &attempts_[1];
      attempt(frame, scaled, retry, options_.min_area_similarity);
      add_retry_times(*retry, result);
      if (retry->choice) a = retry;
    }
  }

  // Still nothing within the gate: an object that starts receding fast (a low frame rate, right
  // after approaching) shrinks past the gate before its shrinking is sustained, and held frames
  // never teach the motion model. One gate step smaller is searched; its boundary must keep the
  // reference shape, as any second search's, and the outline it shrank from must be gone (a
  // cycle inside the object, found while the object's own outline is missed, is not followed).
  if (!a->choice && options_.predict_motion && options_.gate_sustained_shrink &&
      monitor_.state() != TrackState::kLost) {
    Attempt* smaller = &attempts_[1];
    attempt(frame, predicted_, smaller, options_.min_area_similarity, /*adapt=*/false,
            boundary_area_ * options_.min_area_similarity);
    add_retry_times(*smaller, result);
    if (smaller->choice) {
      if (!smaller->assessed) assess(smaller, boundary_);
      if (trusted(*smaller, /*adapted=*/true) && outline_left(*smaller, predicted_)) {
        a = smaller;
        found_smaller_ = true;
      }
    }
  }

  // Lost: the boundary may have moved out of the search band (fast motion, camera swing).
  // Estimate how the content around it moved since it was last tracked, and search again there.
  // After a cut of the view the image motion measures nothing (a look-alike left in place
  // would be found by it).
  if (!a->choice && options_.recover_by_motion && !reference_gray_.empty() &&
      !monitor_.after_cut()) {
    const Clock::time_point recover_start = Clock::now();
    cv::Mat current;
    to_exposed_gray(frame(reference_roi_), &current);
    const std::optional<TranslationEstimate> motion =
        translation_.estimate(reference_gray_, current);
    result->stages.recovery_ms = elapsed_ms(recover_start);
    result->grouping_ms += result->stages.recovery_ms;
    // A move well inside the search band was already searched; re-searching near the same place
    // only invites a worse cycle, so only a move of at least half the band is followed.
    if (motion && cv::norm(motion->shift) >= 0.5 * options_.filter_distance) {
      Polygon moved = boundary_;
      for (Point& p : moved) p += motion->shift;
      Attempt* retry = &attempts_[1];
      attempt(frame, moved, retry, options_.min_area_similarity);
      add_retry_times(*retry, result);
      if (retry->choice) {
        a = retry;
        result->recovered = true;
      }
    }
  }
  return a;
}

void Tracker::assess(Attempt* a, const Polygon& previous) const {
  a->assessed = true;
  if (!a->choice) return;
  a->boundary = a->cycles->polygon(a->graph, a->choice->index);
  a->evidence = evidence_of(*a, a->boundary, previous, &a->descriptor);
  a->confidence = options_.confidence(a->evidence);
}

bool Tracker::trusted(const Attempt& a, bool adapted) const {
  // Lowered thresholds close many more cycles, as a search for a lost object tests many more:
  // their boundary must also keep the reference shape, as a re-found object's must.
  return a.choice && a.confidence >= options_.loss.tracking_confidence &&
         (!adapted || a.evidence.shape_change <= options_.loss.match_shape_distance);
}

Tracker::Attempt* Tracker::retry_weak(const cv::Mat& frame, Attempt* first, const Polygon& prior,
                                      Attempt* retry, TrackResult* result, double gate_area) {
  assess(first, boundary_);
  const bool first_adapted = adapted_first_;
  if (trusted(*first, first_adapted)) return first;
  if (!first_adapted) {
    // A dim or blurred frame's boundary falls below the published thresholds, a noisy frame's
    // breaks into fragments: is there anything lower (or smoother) to look with?
    EdgeThresholds thresholds;
    AdaptiveThresholdOptions this_window = options_.adaptive_thresholds;
    this_window.enabled = true;
    this_window.smooth_noise = false;
    adapt_to_frame(gray_, first->roi.tl(), prior, gradient_threshold_, anchor_threshold_,
                   this_window, nullptr, &thresholds, camera_noise(gray_));
    const bool smooths =
        options_.adaptive_thresholds.smooth_noise &&
        smoothing_for_noise(thresholds.noise_sigma, options_.adaptive_thresholds) > 0.0;
    if (thresholds.gradient >= gradient_threshold_ && !smooths) return first;
  } else if (first->thresholds.gradient >= gradient_threshold_ &&
             first->thresholds.pre_smoothing == 0.0) {
    return first;  // the adapted search was the published one
  }
  attempt(frame, prior, retry, options_.min_area_similarity, !first_adapted, gate_area);
  add_retry_times(*retry, result);
  assess(retry, boundary_);
  // Only a trusted boundary replaces the first search's: lowered thresholds find some closed cycle
  // in almost any textured window, and a held frame (or a motion recovery) is better than that.
  if (trusted(*retry, !first_adapted)) {
    if (options_.adaptive_thresholds.keep_retry_winner) adapted_first_ = !first_adapted;
    return retry;
  }
  // An adapted search's boundary of another shape is not taken either.
  if (first_adapted && first->choice &&
      first->evidence.shape_change > options_.loss.match_shape_distance) {
    first->choice.reset();
  }
  // The retry converted the same window into gray_: the first attempt's evidence stays valid.
  return first;
}

TrackResult Tracker::track(const cv::Mat& frame) {
  if (!initialized()) throw std::logic_error("Tracker::track called before init");
  if (frame.empty()) to_gray(frame, &gray_);  // throws
  check_frame_size(frame, frame_size_);
  scale_thresholds_to_exposure(frame);
  ++frames_since_noise_estimate_;
  if (monitor_.state() == TrackState::kLost) return track_lost(frame);
  TrackResult result;
  Attempt* a = search(frame, &result);

  if (a->choice) {
    // Before the grey window is handed to the motion reference, and against the previous boundary.
    if (!a->assessed) assess(a, boundary_);
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
    // This frame's appearance replaces a pending one, which need not be read first.
    if (options_.predict_motion && options_.confirm_motion) appearance_pending_ = false;
    remember_reference(frame, *a);
    motion_.update(boundary_);
    remember_appearance(frame);
  } else {
    result.held = true;
    check_view_cut(frame, result);
    motion_.update_held();
  }
  // A found boundary's descriptor came with its evidence (assess): the monitor needs no other.
  result.state =
      monitor_.update(boundary_, result.confidence, result.held, result.evidence,
                      result.held ? nullptr : &a->descriptor, result.recovered || found_smaller_);
  if (result.state == TrackState::kTracking) {
    keyframes_.offer(frame, boundary_);
    if (options_.shape_weight > 0.0) shape_memory_.remember(boundary_);
  }
  if (result.state == TrackState::kLost && !result.held) {
    // Lost on a boundary found but not trusted: back to the newest confident one. Lost on a held
    // frame, the held boundary stays (the last found, nearest to where the object went).
    boundary_ = monitor_.latest_confident();
    boundary_area_ = area(boundary_);
  }
  if (result.state == TrackState::kLost) lost_output_ = boundary_;

  result.boundary = boundary_;
  report_attempt(*a, &result);
  return result;
}

}  // namespace scbt
