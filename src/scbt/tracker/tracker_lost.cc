// The tracker's loss handling: the confidence of each tracked frame, and the search for the object
// while it is lost (TrackState::kLost).
#include <algorithm>
#include <chrono>
#include <opencv2/imgproc.hpp>

#include "scbt/lines/line_detector.h"
#include "scbt/tracker/stage_clock.h"
#include "scbt/tracker/tracker_impl.h"
#include "scbt/tracker/view_cut.h"

namespace scbt {
namespace {

// A Sobel response of `threshold` is a grey step of about threshold / 4 (the 3x3 Sobel kernel
// weighs a step 1 + 2 + 1): the smallest step the detector sees as an edge.
double min_edge_step(int gradient_threshold) { return gradient_threshold / 4.0; }

// A re-found object may be a little larger or smaller than when it was lost: the area gate of
// the search around a placement is relaxed to this (the shape must then match).
constexpr double kSearchSimilarity = 0.8;
// Scale steps of the placements beyond the moderate ones: 1 / sqrt(kSearchSimilarity) = 1.12 either
// way of a placement is within the search's area gate.
constexpr double kCoarseScaleStep = 1.2;

}  // namespace

BoundaryEvidence Tracker::Impl::evidence_of(const Attempt& a, const Polygon& chosen,
                                            const Polygon& previous,
                                            ShapeDescriptor* descriptor) const {
  const double gap_length = a.choice->cost * a.cycles->area(a.choice->index);
  BoundaryEvidence evidence =
      measure_evidence(chosen, gap_length, previous, monitor_.reference(), gray_, a.roi.tl(),
                       min_edge_step(step_threshold_), descriptor);
  evidence.inside_level = unstretched_level(exposure_stretch_, evidence.inside_level);
  return evidence;
}

bool Tracker::Impl::outline_left(const Attempt& a, const Polygon& left) const {
  const EdgeSamples there = sample_edges(left, gray_, a.roi.tl(), min_edge_step(step_threshold_));
  return there.support < a.evidence.edge_support;
}

void Tracker::Impl::check_view_cut(const cv::Mat& frame, const TrackResult& result) {
  const LossOptions& loss = options_.loss;
  const bool surprise = result.held || result.confidence < loss.tracking_confidence ||
                        result.evidence.shape_change > loss.match_shape_distance;
  if (monitor_.state() != TrackState::kTracking || !surprise || reference_gray_.empty()) return;
  to_exposed_gray(frame(reference_roi_), &cut_gray_);
  const ViewComparison views(reference_gray_, cut_gray_);
  if (views.whole() < loss.cut_correlation) {
    monitor_.note_view_cut();
    return;
  }
  // The boundary the reference was taken with (not moved since: held, or this frame's not yet
  // taken), in the window's pixels.
  Polygon in_window = boundary_;
  for (Point& p : in_window) p -= Point(reference_roi_.x, reference_roi_.y);
  if (views.surroundings(in_window) < loss.cut_correlation) {
    monitor_.note_view_cut();
  }
}

TrackResult Tracker::Impl::track_lost(const cv::Mat& frame) {
  TrackResult result;
  // kInPlace. After a cut of the view, where the object was says nothing: only the whole frame.
  if (!monitor_.after_cut() && resume_in_place(frame, &result)) return result;
  // kMemory: the remembered outline found where it was, its edges seen again (an occluder left).
  // Also after a cut: an occluder over the object changes the view as much as a cut does, and the
  // remembered edges seen where the object was are the object, not a look-alike.
  MemoryFit seen;
  const MemoryResume memory = resume_from_memory(frame, &result, &seen);
  if (memory == MemoryResume::kResumed) return result;
  // Still lost this frame unless the whole frame gives a match; the in-place search's time counts.
  const double in_place_line_ms = result.line_ms, in_place_grouping_ms = result.grouping_ms;
  result = TrackResult();
  result.state = TrackState::kLost;
  result.held = true;
  result.visible = 0.0;
  result.line_ms = in_place_line_ms;
  result.grouping_ms = in_place_grouping_ms;
  // Not found this frame: the last confident boundary stays the output. Where the memory sees
  // the object partly, where its visible part puts it is the better guess: `uncertain`, as a
  // stand-in with as little seen is while tracking.
  const auto still_lost = [this, &result, &seen, memory]() {
    result.confidence = 0.0;
    result.boundary = lost_output_;
    if (memory == MemoryResume::kPartlySeen) {
      result.boundary = seen.outline;
      result.state = TrackState::kUncertain;
      result.held = false;
      report_memory_fit(seen, &result);
    }
    return result;
  };
  // No match: nothing pending.
  const auto no_match = [this, &still_lost]() {
    pending_.clear();
    pending_matches_ = 0;
    return still_lost();
  };
  // kWholeFrame: the last confident outline placed over the frame, every placement searched.
  const Clock::time_point line_start = Clock::now();
  to_exposed_gray(frame, &search_gray_);
  const std::vector<Segment> segments =
      detector_->detect_in(search_gray_, cv::Point(0, 0), frame_size_);
  result.line_ms += elapsed_ms(line_start);

  const Clock::time_point rank_start = Clock::now();
  std::vector<Placement> placements;
  const size_t beyond_count = place_over_frame(segments, &placements);
  result.stages.recovery_ms = elapsed_ms(rank_start);
  result.grouping_ms += result.stages.recovery_ms;

  // Where the memory sees the object partly, matches are judged by its fit, and for a while after
  // it last did by that fit (held): under an occluder that stays, what it sees of the object comes
  // and goes, and a cycle cut short across the occluder must not slip in meanwhile.
  if (memory == MemoryResume::kPartlySeen) {
    last_partly_seen_ = seen;
    partly_seen_age_ = 0;
  } else if (last_partly_seen_.valid && ++partly_seen_age_ > kPartlySeenHold) {
    last_partly_seen_ = MemoryFit();
  }
  const MemoryFit* partly_seen = last_partly_seen_.valid ? &last_partly_seen_ : nullptr;
  // There first (after last frame's match).
  if (partly_seen) {
    placements.insert(placements.begin() + (pending_.empty() ? 0 : 1),
                      Placement{partly_seen->outline, 0.0, true, 1.0});
  }
  const bool held = partly_seen && memory != MemoryResume::kPartlySeen;
  Polygon match = best_match(frame, placements, beyond_count, partly_seen, held, &result);
  result.num_detected = static_cast<int>(segments.size());
  if (keep_debug_) debug_.detected = segments;
  if (match.empty()) return no_match();
  const bool same_place = !pending_.empty() && cv::norm(centroid(match) - centroid(pending_)) <=
                                                   0.25 * std::sqrt(area(match));
  pending_matches_ = same_place ? pending_matches_ + 1 : 1;
  pending_ = match;
  // Not yet trusted: still lost (the match's confidence is not the output's).
  // A match the held fit would reject must be found as often as a new view must be seen: the
  // held fit may be stale (the object moved on while it was not seen).
  const int confirm = match_unvetted_ ? std::max(kNewViewFrames, options_.loss.confirm_frames)
                                      : options_.loss.confirm_frames;
  if (pending_matches_ < confirm) return still_lost();
  result.num_kept = match_kept_;
  result.num_vertices = match_graph_.num_vertices();
  result.num_edges = match_graph_.num_edges();
  if (keep_debug_) debug_.graph = match_graph_;
  result.step = SearchStep::kWholeFrame;
  // A match the memory's partial fit vouched for keeps the memory's outline.
  resume_tracking_from(frame, std::move(match), &result, partly_seen && !match_unvetted_);
  return result;
}

size_t Tracker::Impl::place_over_frame(const std::vector<Segment>& segments,
                                       std::vector<Placement>* placements) {
  const LossOptions& loss = options_.loss;
  PlacementOptions placement_options;
  placement_options.min_scale = loss.min_scale;
  placement_options.max_scale = loss.max_scale;
  placement_options.near_tries = loss.near_tries;
  placement_options.frame_tries = loss.frame_tries;
  reacquirer_.set_segments(segments, frame_size_, 0.5 * options_.filter_distance);
  *placements = reacquirer_.rank(monitor_.last_confident(), placement_options);
  // Nearer or further than the moderate scales: a few more placements, whose matches must also
  // look like the object's last kept view (reacquire_view_change.h).
  cv::Mat view;
  Polygon view_boundary;
  const ViewChangeOptions& view_change = loss.view_change;
  size_t beyond_count = 0;  // the last placements: beyond the moderate scales
  if (view_change.enabled && keyframes_.view(&view, &view_boundary)) {
    // Smaller and larger apart (the chamfer distance favours small outlines in clutter), in
    // coarser steps (each costs a scoring of the whole frame; the area gate of the search around
    // a placement, kSearchSimilarity, still spans them).
    PlacementOptions smaller = placement_options, larger = placement_options;
    smaller.near_tries = larger.near_tries = 0;
    smaller.frame_tries = larger.frame_tries = view_change.frame_tries;
    smaller.scale_step = larger.scale_step = kCoarseScaleStep;
    smaller.min_scale = view_change.min_scale;
    smaller.max_scale = loss.min_scale / placement_options.scale_step;
    larger.min_scale = loss.max_scale * placement_options.scale_step;
    larger.max_scale = view_change.max_scale;
    for (const PlacementOptions* band : {&larger, &smaller}) {
      if (band->min_scale > band->max_scale) continue;
      const std::vector<Placement> beyond = reacquirer_.rank(monitor_.last_confident(), *band);
      placements->insert(placements->end(), beyond.begin(), beyond.end());
      beyond_count += beyond.size();
    }
    // Seen from a little lower or higher: the outline flatter or rounder by the square root of
    // the foreshortening allowed (the search band around it covers the rest), near where it was
    // (scored there only), at the moderate scales in coarse steps.
    PlacementOptions turned = placement_options;
    turned.near_tries = 1;
    turned.frame_tries = 0;
    turned.scale_step = kCoarseScaleStep;
    const double f = std::sqrt(view_change.max_foreshortening);
    for (double factor : {1.0 / f, f}) {
      const std::vector<Placement> beyond =
          reacquirer_.rank(foreshortened(monitor_.last_confident(), factor), turned);
      placements->insert(placements->end(), beyond.begin(), beyond.end());
      beyond_count += beyond.size();
    }
  }
  view_change_.set_reference(monitor_.last_confident(), view, view_boundary);
  // Where the scene says the object is now, and how large (a camera move or a jump while it was
  // hidden): that placement, then the best ones around it at its scale.
  const std::optional<RegisteredBoundary> registered = keyframes_.locate(search_gray_);
  if (registered) {
    std::vector<Placement> around = reacquirer_.rank(registered->boundary, placement_options);
    around.insert(around.begin(), Placement{registered->boundary, 0.0, true, registered->scale});
    placements->insert(placements->begin(), around.begin(), around.end());
  }
  // First where it was last seen, as it was (a blank or occluded stretch rarely moves it far),
  // and before that last frame's match, where it was found.
  placements->insert(placements->begin(), Placement{monitor_.latest_confident(), 0.0, true, 1.0});
  if (!pending_.empty())
    placements->insert(placements->begin(), Placement{pending_, 0.0, true, 1.0});
  return beyond_count;
}

bool Tracker::Impl::along_partial_fit(const Polygon& cycle, const MemoryFit& partly_seen) const {
  // Where the partial fit is (its hidden part predicted, less exactly) ...
  const double near = agreement_distance(partly_seen.outline);
  if (memory_.mismatch(cycle, partly_seen.outline, 2.0 * near) > kAgreeMismatch) return false;
  // ... and the remembered outline, in some view: a cycle cut short or widened by an occluder
  // still in front departs from the outline mapped onto it.
  const Polygon mapped = memory_.mapped_onto(cycle);
  return !mapped.empty() && memory_.mismatch(cycle, mapped, near) <= kAgreeMismatch;
}

Polygon Tracker::Impl::best_match(const cv::Mat& frame, const std::vector<Placement>& placements,
                                  size_t beyond_count, const MemoryFit* partly_seen, bool held,
                                  TrackResult* result) {
  const LossOptions& loss = options_.loss;
  // Every placement is searched and the best match kept (a look-alike found first must not hide
  // the object found later); last frame's match found again is taken at once.
  const double similarity = std::min(options_.min_area_similarity, kSearchSimilarity);
  Attempt* a = &attempts_[1];
  Polygon match;
  double best_score = 0.0;
  for (size_t i = 0; i < placements.size(); ++i) {
    const Placement& placement = placements[i];
    attempt(frame, placement.outline, a, similarity);
    result->line_ms += a->line_ms;
    result->grouping_ms += a->grouping_ms;
    result->num_candidates += a->cycles->num_candidates();
    if (!a->choice) continue;
    Polygon cycle = a->cycles->polygon(a->graph, a->choice->index);
    const BoundaryEvidence evidence = evidence_of(*a, cycle, placement.outline);
    const double confidence = options_.confidence(evidence);
    // Beyond the moderate scales only a match that also looks like the object counts: there a
    // small or large piece of clutter of the object's shape is far more likely than the object.
    const bool beyond = i + beyond_count >= placements.size();
    double shape = 0.0;
    bool view_changed = false;
    bool along_fit = false;
    if (!beyond && monitor_.matches(cycle, evidence, confidence)) {
      shape = shape_distance(shape_descriptor(cycle), monitor_.reference());
    } else if (!beyond && partly_seen && confidence >= loss.reacquire_confidence &&
               along_partial_fit(cycle, *partly_seen)) {
      // Closed along the outline the memory's own edges put there: the object, though its view
      // or the light on it changed while it was lost (its shape or inside level with them).
      along_fit = true;
      shape = std::min(loss.match_shape_distance,
                       shape_distance(shape_descriptor(cycle), monitor_.reference()));
    } else if (confidence >= loss.reacquire_confidence) {
      // Seen from another distance or angle, and looking like the object inside.
      const std::optional<double> d =
          view_change_.distance(frame, cycle, loss.match_shape_distance);
      if (!d) continue;
      shape = *d;
      view_changed = true;
    } else {
      continue;
    }
    // Where the memory sees the object partly, a match must show it more of itself than that.
    // Judged by a held fit (perhaps stale), one that does not ranks after every other, marked.
    bool unvetted = false;
    if (partly_seen && !along_fit &&
        memory_.fit_at(cycle, search_gray_, {0, 0}).visible <= partly_seen->visible) {
      if (!held) continue;
      unvetted = true;
    }
    // Both terms are in [0, 1] for a match: how close the shape is, how sure the cycle is. A
    // match seen from another distance or angle comes after every ordinary one: an object rarely
    // changes its size or its view much while out of sight, and the inside of a see-through or
    // plain object looks much like a smaller cycle within it.
    const double score = shape / loss.match_shape_distance + (1.0 - confidence) +
                         (view_changed ? 2.0 : 0.0) + (unvetted ? 4.0 : 0.0);
    if (!match.empty() && score >= best_score) continue;
    best_score = score;
    result->evidence = evidence;
    result->confidence = confidence;
    result->cost = a->choice->cost;
    result->area_similarity =
        area_similarity(area(monitor_.last_confident()), a->cycles->area(a->choice->index));
    match = std::move(cycle);
    match_graph_ = a->graph;
    match_kept_ = static_cast<int>(a->kept.size());
    match_unvetted_ = unvetted;
    if (i == 0 && !pending_.empty() && !view_changed) break;
  }
  return match;
}

}  // namespace scbt
