// The tracker's use of the object memory while tracking: its fit each frame, its verdict on the
// cycle chosen, what it learns from a confident one, and how sure a frame is against it.
#include <algorithm>
#include <cmath>

#include "scbt/tracker/tracker_impl.h"

namespace scbt {

void Tracker::Impl::report_memory_fit(const MemoryFit& fit, TrackResult* result) {
  result->visible = fit.visible;
  result->confidence = fit.visible;
  result->from_memory = true;
  result->step = SearchStep::kMemory;
}

MemoryFit Tracker::Impl::search_memory(const cv::Mat& frame, double accept_visible) {
  const double radius = std::min(kMemorySearchMax, 0.5 * std::sqrt(area(memory_.placed())));
  const cv::Rect roi =
      detection_roi(memory_.placed(), radius + options_.memory.search_px, frame_size_);
  if (roi.empty()) {
    // No window this frame: none to fit the former memory to either (resume_from_memory).
    memory_gray_.release();
    return {};
  }
  to_exposed_gray(frame(roi), &memory_gray_);
  memory_gray_tl_ = roi.tl();
  return memory_.search(memory_gray_, roi.tl(), radius, accept_visible);
}

Tracker::Impl::MemoryCheck Tracker::Impl::check_with_memory(const cv::Mat& frame, Attempt* a) {
  MemoryCheck check;
  check.fit = memory_.fit(gray_, gray_roi_.tl());
  check.verdict = judge_by_memory(a, check.fit);
  if (check.verdict != MemoryVerdict::kAgrees &&
      (!check.fit.valid || check.fit.visible < kResumeVisible)) {
    // Neither the cycle nor the memory where it was placed sees the object well: the memory is
    // looked for around (it may have slipped while the object was hidden).
    const MemoryFit found = search_memory(frame, kResumeVisible);
    if (found.valid) {
      check.fit = found;
      check.verdict = judge_by_memory(a, check.fit);
    }
  }
  if (check.verdict != MemoryVerdict::kAgrees && former_memory_.ready()) {
    // A restart on a wrong cycle (an occluder's cut taken for a new view) is undone when the
    // memory before it sees the object better, where the cycle or the fit puts it.
    if (a->choice && !a->assessed) assess(a, boundary_);
    MemoryFit back;
    if ((a->choice &&
         return_to_former_memory(a->boundary, check.fit, gray_, gray_roi_.tl(), &back)) ||
        (check.fit.valid &&
         return_to_former_memory(check.fit.outline, check.fit, gray_, gray_roi_.tl(), &back))) {
      check.fit = back;
      check.verdict = judge_by_memory(a, back);
    }
  }
  // A new view stays; an occluder passing in front changes the cycle's cut frame by frame (a
  // hand's fingers over a rim pass as the object's own edges in grey): the memory takes a new
  // view only after kNewViewFrames frames in a row show one, and meanwhile follows no cycle.
  new_view_frames_ = check.verdict == MemoryVerdict::kNewView ? new_view_frames_ + 1 : 0;
  if (check.verdict == MemoryVerdict::kNewView && new_view_frames_ < kNewViewFrames) {
    check.verdict = MemoryVerdict::kDeparts;
  }
  check.new_view_seen = check.verdict == MemoryVerdict::kNewView;
  if (memory_provisional_ > 0) {
    --memory_provisional_;
    if (check.verdict == MemoryVerdict::kDeparts || check.verdict == MemoryVerdict::kStandsIn) {
      check.verdict = MemoryVerdict::kNewView;
    }
  }
  return check;
}

bool Tracker::Impl::return_to_former_memory(const Polygon& outline, const MemoryFit& current,
                                            const cv::Mat& gray, cv::Point tl, MemoryFit* back) {
  if (!former_memory_.ready() || outline.empty()) return false;
  const MemoryFit former = former_memory_.fit_at(outline, gray, tl);
  if (!former.valid || former.visible < kResumeVisible ||
      (current.valid && former.visible <= current.visible)) {
    return false;
  }
  memory_ = std::move(former_memory_);
  former_memory_.clear();
  memory_.place_at(former.outline);
  new_view_frames_ = 0;
  memory_provisional_ = 0;
  *back = former;
  return true;
}

void Tracker::Impl::learn_from_cycle(const MemoryCheck& check, cv::Point tl) {
  switch (check.verdict) {
    case MemoryVerdict::kAgrees:
      // All of it seen and followed: nothing hides a part the cycle could have cut off, so the
      // memory's shape moves towards the cycle's, slowly; otherwise only its place and view.
      memory_.remember(boundary_, gray_, tl,
                       check.fit.visible >= kReshapeVisible ? kShapeRate : 0.0);
      break;
    case MemoryVerdict::kUnjudged:
      memory_.remember(boundary_, gray_, tl);
      break;
    case MemoryVerdict::kNewView:
      if (check.new_view_seen) former_memory_ = memory_;
      memory_.restart(boundary_, gray_, tl);
      break;
    case MemoryVerdict::kDeparts:
    case MemoryVerdict::kStandsIn:
      break;
  }
}

Tracker::Impl::MemoryVerdict Tracker::Impl::judge_by_memory(Attempt* a, const MemoryFit& fit) {
  if (!fit.valid) return MemoryVerdict::kUnjudged;
  if (!a->choice) {
    // Too little of the object seen to place it from the memory alone.
    return fit.visible >= kPredictVisible ? MemoryVerdict::kStandsIn : MemoryVerdict::kUnjudged;
  }
  if (!a->assessed) assess(a, boundary_);
  // A cycle along the fitted outline (within a few pixels, or a twentieth of the object's size)
  // but for a small part is the object: kept as found, to the pixel.
  const double near = agreement_distance(fit.outline);
  if (memory_.mismatch(a->boundary, fit.outline, near) <= kAgreeMismatch) {
    return MemoryVerdict::kAgrees;
  }
  // Departing along edges like the object's own: its shape changed, which the memory follows.
  const bool own_departure =
      memory_.departure_support(a->boundary, fit.outline, near, gray_, gray_roi_.tl()) >= 0.7;
  // The object's edges, all but a small part, are on the cycle, and where it departs it runs
  // along edges like the object's: the view changed beyond what the memory's outline can follow.
  // (A cycle cutting across a small occluder also runs along most of the object's edges, but
  // departs along the occluder's.)
  if (own_departure && memory_.explained_by(a->boundary, fit.outline, near, gray_,
                                            gray_roi_.tl()) >= kNewViewExplained) {
    return MemoryVerdict::kNewView;
  }
  if (fit.visible < kPredictVisible) return MemoryVerdict::kDeparts;
  return own_departure ? MemoryVerdict::kDeparts : MemoryVerdict::kStandsIn;
}

bool Tracker::Impl::departs_after_stand_in(const MemoryCheck& check, const Attempt& a) const {
  if (!options_.object_memory || !memory_.ready() || !a.choice ||
      frames_since_stand_in_ > kPartlySeenHold ||
      (check.verdict != MemoryVerdict::kDeparts && check.verdict != MemoryVerdict::kUnjudged)) {
    return false;
  }
  // Taken within a second of the memory standing in for the partly hidden object, but most of it
  // away from the memory: an occluder's outline closing the best cycle while the memory sees too
  // little to stand in.
  const Polygon& remembered = check.fit.valid ? check.fit.outline : memory_.placed();
  return !remembered.empty() &&
         memory_.mismatch(a.boundary, remembered, agreement_distance(remembered)) >
             kElsewhereMismatch;
}

void Tracker::Impl::doubt_departure_from_memory(TrackResult* result) const {
  // The frame is only as sure as the memory's view of the object.
  result->confidence = std::min(result->confidence, result->visible);
  if (result->confidence < options_.min_visible) result->state = TrackState::kUncertain;
}

}  // namespace scbt
