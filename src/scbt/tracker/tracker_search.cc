// A tracking frame's search (Tracker::Impl::search): the steps of tracker.h's SearchStep, in
// order, each a function of one signature; the weak-frame retry they share, the checks a second
// search's boundary must pass, and the appearance that confirms a prediction.
#include <opencv2/core.hpp>
#include <optional>

#include "scbt/lines/line_detector.h"
#include "scbt/motion/motion_estimate.h"
#include "scbt/tracker/stage_clock.h"
#include "scbt/tracker/tracker_impl.h"

namespace scbt {

void Tracker::Impl::add_retry_times(const Attempt& retry, TrackResult* result) {
  result->line_ms += retry.line_ms;
  result->grouping_ms += retry.grouping_ms;
  result->stages.filter_ms += retry.stages.filter_ms;
  result->stages.graph_ms += retry.stages.graph_ms;
  result->stages.search_ms += retry.stages.search_ms;
  result->stages.choice_ms += retry.stages.choice_ms;
}

void Tracker::Impl::remember_appearance(const cv::Mat& frame) {
  if (!options_.predict_motion || !options_.confirm_motion) return;
  appearance_pending_ = false;
  if (keeps_motion_reference() && !reference_gray_.empty()) {
    appearance_boundary_ = boundary_;
    appearance_pending_ = true;
  } else {
    appearance_.remember(frame, boundary_);
  }
}

void Tracker::Impl::settle_appearance() {
  if (!appearance_pending_) return;
  appearance_pending_ = false;
  // The reference window holds the boundary with the profile's few pixels either side (it is
  // the search band's), unless the frame's edge cuts both alike.
  for (Point& p : appearance_boundary_) p -= Point(reference_roi_.x, reference_roi_.y);
  appearance_.remember(reference_gray_, appearance_boundary_);
}

bool Tracker::Impl::confirmed(const cv::Mat& frame, const Polygon& moved, const Polygon& unmoved) {
  settle_appearance();
  const double agreement = appearance_.agreement(frame, moved);
  return agreement >= options_.min_motion_agreement &&
         agreement > appearance_.agreement(frame, unmoved);
}

void Tracker::Impl::predict_placement(const cv::Mat& frame) {
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
}

Tracker::Impl::Attempt* Tracker::Impl::search(const cv::Mat& frame, TrackResult* result) {
  // The steps in SearchStep's order; each decides for itself whether it runs (tracker.h).
  struct Step {
    SearchStep id;
    StepOutcome (Impl::*run)(const cv::Mat& frame, FrameSearch* s);
  };
  static constexpr Step kSteps[] = {
      {SearchStep::kPredicted, &Impl::search_predicted},
      {SearchStep::kUnmoved, &Impl::search_unmoved},
      {SearchStep::kGrowth, &Impl::search_growth},
      {SearchStep::kSmaller, &Impl::search_smaller},
      {SearchStep::kImageMotion, &Impl::search_image_motion},
  };
  predict_placement(frame);
  FrameSearch s;
  s.result = result;
  // At a low frame rate an object receding steadily shrinks by more than the gate between frames.
  // The gate then compares with the shrunken area; never with a grown one, since Γ already favours
  // larger cycles and a cycle creeping outward grows steadily too.
  s.gate_area = options_.predict_motion && options_.gate_sustained_shrink &&
                        monitor_.state() != TrackState::kLost
                    ? boundary_area_ * motion_.sustained_shrink_ratio()
                    : 0.0;
  // Not while lost: the search there (tracker_resume.cc) asks for the last confident shape, which
  // the published thresholds found; lowered ones invite a different cycle in its place.
  s.retry_weak_frames = options_.adaptive_thresholds.retry_weak_frames &&
                        !options_.adaptive_thresholds.enabled && detector_->adapts_thresholds() &&
                        monitor_.state() != TrackState::kLost;
  s.adapted_first = s.retry_weak_frames && adapted_first_;
  s.adapted_next = adapted_first_;
  for (const Step& step : kSteps) {
    const StepOutcome outcome = (this->*step.run)(frame, &s);
    if (outcome.taken) {
      s.found = outcome.searched;
      s.step = step.id;
    }
  }
  adapted_first_ = s.adapted_next;
  Attempt* a = s.found;
  // The grey window must be the chosen attempt's (its evidence, the motion reference).
  if (a->choice && a->roi != gray_roi_) {
    to_exposed_gray(frame(a->roi), &gray_);
    gray_roi_ = a->roi;
  }
  result->step = a->choice ? s.step : SearchStep::kNone;
  result->recovered = result->step == SearchStep::kImageMotion;
  return a;
}

Tracker::Impl::StepOutcome Tracker::Impl::search_predicted(const cv::Mat& frame, FrameSearch* s) {
  Attempt* a = &attempts_[0];
  attempt(frame, predicted_, a, options_.min_area_similarity, s->adapted_first, s->gate_area);
  s->result->line_ms = a->line_ms;
  s->result->grouping_ms = a->grouping_ms;
  s->result->stages = a->stages;
  if (s->retry_weak_frames)
    a = retry_weak(frame, a, predicted_, &attempts_[1], s, &s->adapted_next);
  return {a, true};
}

Tracker::Impl::StepOutcome Tracker::Impl::search_unmoved(const cv::Mat& frame, FrameSearch* s) {
  // A prediction can be wrong (a blurred frame's measured motion, a camera that stopped): when
  // nothing trusted was found where it points, where the boundary was is searched as well.
  if (!options_.fall_back_unmoved || predicted_ == boundary_) return {};
  if (!s->found->assessed) assess(s->found, boundary_);
  if (trusted(*s->found, /*adapted=*/false)) return {};
  Attempt* unmoved = &attempts_[2];
  attempt(frame, boundary_, unmoved, options_.min_area_similarity, s->adapted_first, s->gate_area);
  add_retry_times(*unmoved, s->result);
  // Its own weak-frame retry starts from the frame's first thresholds, and decides the next
  // frame's only when its boundary is taken.
  bool adapted_next = s->adapted_first;
  if (s->retry_weak_frames) {
    unmoved = retry_weak(frame, unmoved, boundary_, &attempts_[3], s, &adapted_next);
  }
  if (!unmoved->assessed) assess(unmoved, boundary_);
  // A second search tests more cycles: its boundary must also keep the reference shape.
  if (!trusted(*unmoved, /*adapted=*/true)) return {unmoved, false};
  s->adapted_next = adapted_next;
  return {unmoved, true};
}

Tracker::Impl::StepOutcome Tracker::Impl::search_growth(const cv::Mat& frame, FrameSearch* s) {
  // No candidate within the area gate of the last boundary: at a low frame rate an object
  // approaching or receding fast grows or shrinks by more than the gate between frames. Search
  // again with the size its recent growth predicts (if the image confirms that size: a growth
  // measured on a mis-tracked frame would otherwise compound).
  if (s->found->choice || !options_.predict_motion ||
      area_similarity(motion_.predicted_area_ratio(), 1.0) > options_.min_area_similarity) {
    return {};
  }
  Polygon scaled;
  motion_.predict(boundary_, /*with_scale=*/true, &scaled);
  if (options_.confirm_motion && !confirmed(frame, scaled, predicted_)) return {};
  Attempt* retry = &attempts_[1];
  attempt(frame, scaled, retry, options_.min_area_similarity);
  add_retry_times(*retry, s->result);
  return {retry, retry->choice.has_value()};
}

Tracker::Impl::StepOutcome Tracker::Impl::search_smaller(const cv::Mat& frame, FrameSearch* s) {
  // Still nothing within the gate: an object that starts receding fast (a low frame rate, right
  // after approaching) shrinks past the gate before its shrinking is sustained, and held frames
  // never teach the motion model. One gate step smaller is searched; its boundary must keep the
  // reference shape, as any second search's, and the outline it shrank from must be gone (a
  // cycle inside the object, found while the object's own outline is missed, is not followed).
  if (s->found->choice || !options_.predict_motion || !options_.gate_sustained_shrink ||
      monitor_.state() == TrackState::kLost) {
    return {};
  }
  Attempt* smaller = &attempts_[1];
  attempt(frame, predicted_, smaller, options_.min_area_similarity, /*adapt=*/false,
          boundary_area_ * options_.min_area_similarity);
  add_retry_times(*smaller, s->result);
  if (!smaller->choice) return {smaller, false};
  if (!smaller->assessed) assess(smaller, boundary_);
  return {smaller, trusted(*smaller, /*adapted=*/true) && outline_left(*smaller, predicted_)};
}

Tracker::Impl::StepOutcome Tracker::Impl::search_image_motion(const cv::Mat& frame,
                                                              FrameSearch* s) {
  // Lost: the boundary may have moved out of the search band (fast motion, camera swing).
  // Estimate how the content around it moved since it was last tracked, and search again there.
  // After a cut of the view the image motion measures nothing (a look-alike left in place
  // would be found by it).
  if (s->found->choice || !options_.recover_by_motion || reference_gray_.empty() ||
      monitor_.after_cut()) {
    return {};
  }
  const Clock::time_point recover_start = Clock::now();
  cv::Mat current;
  to_exposed_gray(frame(reference_roi_), &current);
  const std::optional<TranslationEstimate> motion = translation_.estimate(reference_gray_, current);
  s->result->stages.recovery_ms = elapsed_ms(recover_start);
  s->result->grouping_ms += s->result->stages.recovery_ms;
  // A move well inside the search band was already searched; re-searching near the same place
  // only invites a worse cycle, so only a move of at least half the band is followed.
  if (!motion || cv::norm(motion->shift) < 0.5 * options_.filter_distance) return {};
  Polygon moved = boundary_;
  for (Point& p : moved) p += motion->shift;
  Attempt* retry = &attempts_[1];
  attempt(frame, moved, retry, options_.min_area_similarity);
  add_retry_times(*retry, s->result);
  return {retry, retry->choice.has_value()};
}

void Tracker::Impl::assess(Attempt* a, const Polygon& previous) const {
  a->assessed = true;
  if (!a->choice) return;
  a->boundary = a->cycles->polygon(a->graph, a->choice->index);
  a->evidence = evidence_of(*a, a->boundary, previous, &a->descriptor);
  a->confidence = options_.confidence(a->evidence);
}

bool Tracker::Impl::trusted(const Attempt& a, bool adapted) const {
  // Lowered thresholds close many more cycles, as a search for a lost object tests many more:
  // their boundary must also keep the reference shape, as a re-found object's must.
  return a.choice && a.confidence >= options_.loss.tracking_confidence &&
         (!adapted || a.evidence.shape_change <= options_.loss.match_shape_distance);
}

Tracker::Impl::Attempt* Tracker::Impl::retry_weak(const cv::Mat& frame, Attempt* first,
                                                  const Polygon& prior, Attempt* retry,
                                                  FrameSearch* s, bool* adapted_next) {
  assess(first, boundary_);
  const bool first_adapted = s->adapted_first;
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
  attempt(frame, prior, retry, options_.min_area_similarity, !first_adapted, s->gate_area);
  add_retry_times(*retry, s->result);
  assess(retry, boundary_);
  // Only a trusted boundary replaces the first search's: lowered thresholds find some closed cycle
  // in almost any textured window, and a held frame (or a motion recovery) is better than that.
  if (trusted(*retry, !first_adapted)) {
    if (options_.adaptive_thresholds.keep_retry_winner) *adapted_next = !first_adapted;
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

}  // namespace scbt
