// Tracking starting again while the object is lost: the first search (tracking's own, where the
// object was, with the bar of a tracked frame), and the one restart both searches end in.
#include <opencv2/core.hpp>

#include "scbt/lines/line_detector.h"
#include "scbt/tracker/tracker_impl.h"

namespace scbt {

bool Tracker::Impl::resume_in_place(const cv::Mat& frame, TrackResult* result) {
  // On a poor camera (dim, noisy, blurred) the object is often missed a few frames in a row
  // without having gone anywhere; the whole-frame search's higher bar (it tests many more cycles)
  // would then keep it lost for as long as the image stays poor.
  const Attempt* a = search(frame, result);
  if (!a->choice) return false;
  Polygon cycle = a->cycles->polygon(a->graph, a->choice->index);
  const BoundaryEvidence evidence = evidence_of(*a, cycle, boundary_);
  const double confidence = options_.confidence(evidence);
  if (!monitor_.matches(cycle, evidence, confidence, options_.loss.tracking_confidence)) {
    // Not trusted, but followed (not output): through a fast swing or a poor stretch of video
    // the object is found again where tracking would have gone, not where it was lost.
    boundary_ = std::move(cycle);
    boundary_area_ = a->cycles->area(a->choice->index);
    remember_reference(*a);
    return false;
  }
  result->evidence = evidence;
  result->confidence = confidence;
  result->cost = a->choice->cost;
  result->area_similarity = a->choice->similarity;
  result->step = SearchStep::kInPlace;
  report_attempt(*a, result);
  resume_tracking_from(frame, std::move(cycle), result);
  return true;
}

Tracker::Impl::MemoryResume Tracker::Impl::resume_from_memory(const cv::Mat& frame,
                                                              TrackResult* result,
                                                              MemoryFit* seen) {
  if (!options_.object_memory || !memory_.ready()) return MemoryResume::kNotSeen;
  // Looked for around where it was: the object may have moved while it was lost.
  *seen = search_memory(frame, kPredictVisible);
  if (former_memory_.ready() && (!seen->valid || seen->visible < options_.min_visible)) {
    // Where the memory is, the one before its last restart may see the object better.
    MemoryFit back;
    if (return_to_former_memory(seen->valid ? seen->outline : memory_.placed(), *seen, memory_gray_,
                                memory_gray_tl_, &back)) {
      *seen = back;
    }
  }
  if (!seen->valid) return MemoryResume::kNotSeen;
  // The remembered edges seen where the object was, as much as a stand-in is `tracking` with:
  // the object, not a look-alike elsewhere. With less, it is there, partly hidden.
  if (seen->visible < options_.min_visible) return MemoryResume::kPartlySeen;
  report_memory_fit(*seen, result);
  resume_tracking_from(frame, seen->outline, result);
  return MemoryResume::kResumed;
}

void Tracker::Impl::resume_tracking_from(const cv::Mat& frame, Polygon boundary,
                                         TrackResult* result, bool vouched_by_memory) {
  result->state = TrackState::kTracking;
  result->held = false;
  result->reacquired = true;
  // The scene keyframes are kept: they are confident views of the object's surroundings, which
  // finding the object again does not make wrong (init() clears them, for a new object).
  monitor_.resume(boundary, result->evidence.inside_level);
  boundary_ = std::move(boundary);
  boundary_area_ = area(boundary_);
  pending_.clear();
  last_partly_seen_ = MemoryFit();
  pending_matches_ = 0;
  frames_since_stand_in_ = kPartlySeenHold + 1;
  // The motion model, the motion reference (the window the next frame's search would look at)
  // and the appearance that confirms predictions start again from this frame.
  motion_.reset();
  motion_.update(boundary_);
  reference_roi_ = detection_roi(
      boundary_, options_.filter_distance + options_.detector.roi_padding, frame_size_);
  if (reference_roi_.empty()) reference_roi_ = cv::Rect(cv::Point(0, 0), frame_size_);
  to_exposed_gray(frame(reference_roi_), &reference_gray_);
  if (options_.predict_motion && options_.confirm_motion) {
    appearance_pending_ = false;
    appearance_.remember(frame, boundary_);
  }
  shape_memory_.restart(boundary_);
  // Found by the memory itself: it keeps what it knows (the object's edges where it is still
  // hidden included), placed where it was found. Vouched for by it: moved onto the match, whose
  // cut across an occluder still in front is not learnt; no look-alike, so no provisional time.
  if (options_.object_memory && !result->from_memory) {
    if (vouched_by_memory) {
      memory_.place_onto(boundary_, reference_gray_, reference_roi_.tl());
    } else {
      if (memory_provisional_ == 0) former_memory_ = memory_;
      memory_.restart(boundary_, reference_gray_, reference_roi_.tl());
      memory_provisional_ = kProvisionalFrames;
    }
  }
  result->boundary = boundary_;
}

}  // namespace scbt
