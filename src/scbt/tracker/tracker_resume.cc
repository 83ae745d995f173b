// The first search while the object is lost: tracking's own search (where the object was, where
// the image moved it), with the bar of a tracked frame. On a poor camera (dim, noisy, blurred) the
// object is often missed a few frames in a row without having gone anywhere; the whole-frame
// search's higher bar (it tests many more cycles) would then keep it lost for as long as the image
// stays poor.
#include "scbt/tracker/tracker.h"

namespace scbt {

bool Tracker::resume_in_place(const cv::Mat& frame, TrackResult* result) {
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
    remember_reference(frame, *a);
    return false;
  }
  result->state = TrackState::kTracking;
  result->held = false;
  result->reacquired = true;
  result->evidence = evidence;
  result->confidence = confidence;
  result->cost = a->choice->cost;
  result->area_similarity = a->choice->similarity;
  monitor_.resume(cycle, evidence.inside_level);
  boundary_ = std::move(cycle);
  boundary_area_ = a->cycles->area(a->choice->index);
  pending_.clear();
  pending_matches_ = 0;
  motion_.reset();
  motion_.update(boundary_);
  remember_reference(frame, *a);
  if (options_.predict_motion && options_.confirm_motion) appearance_.remember(frame, boundary_);
  result->boundary = boundary_;
  report_attempt(*a, result);
  return true;
}

}  // namespace scbt
