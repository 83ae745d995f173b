// The per-frame salient closed boundary tracker: detect -> filter -> gap fill -> BDSP -> choose.
#pragma once

#include <memory>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "scbt/geometry/polygon.h"
#include "scbt/graph/segment_graph.h"
#include "scbt/tracker/confidence.h"
#include "scbt/tracker/track_state.h"
#include "scbt/tracker/tracker_options.h"

namespace scbt {

// The steps of a frame's search, in the order they run; a frame reports the step whose boundary
// it took (TrackResult::step). While tracking, a step after the first runs only when the ones
// before it found nothing (kUnmoved: nothing trusted), and its boundary is taken when it passes
// the step's test:
//   kPredicted    where the boundary is, or where its motion puts it (predict_motion,
//                 measure_motion); a weak frame is searched again with the other thresholds
//                 (AdaptiveThresholdOptions::retry_weak_frames). Taken as found.
//   kUnmoved      where the boundary was, when the prediction moved it and found nothing trusted
//                 (fall_back_unmoved). Taken when trusted and of the reference shape.
//   kGrowth       with the size its recent growth predicts, when that is beyond the area gate
//                 (and the image confirms it, confirm_motion). Taken when a cycle passes the gate.
//   kSmaller      one area-gate step smaller (gate_sustained_shrink): a fast receding object.
//                 Taken when trusted, of the reference shape, and the outline it shrank from is
//                 gone.
//   kImageMotion  where the image around it moved since it was last tracked (recover_by_motion),
//                 a move of at least half the search band. Taken when a cycle passes the gate.
//   kMemory       the remembered outline fitted to the visible part of the object
//                 (TrackerOptions::object_memory), when the step above found no cycle, or one that
//                 departs from the fitted outline along part of it without the object's edges
//                 there; taken when at least 35 % of it is seen (`tracking` from
//                 TrackerOptions::min_visible on, `uncertain` below).
// While the object is lost (TrackState::kLost):
//   kInPlace      the tracking steps above, their boundary taken when it matches the last
//                 confident one with the tracking bar (LossOptions::tracking_confidence).
//   kMemory       the remembered outline looked for where the object was and around it
//                 (object_memory), also after a cut, taken when TrackerOptions::min_visible of it
//                 is seen again; with 35 % seen the object is there, partly hidden: the fitted
//                 outline is the output (`uncertain`), and kWholeFrame searches there first and
//                 takes a cycle along it though its shape or inside level changed (another view
//                 or light), elsewhere a match on which the memory, fitted there, sees more of
//                 itself, or for a second after that fit one found 5 frames in a row.
//   kWholeFrame   the last confident outline placed over the whole frame (where it was last
//                 matched and seen, where the scene keyframes put it, the best-scoring places, then
//                 other sizes and views), every placement searched and the best match taken once
//                 found LossOptions::confirm_frames times in a row.
enum class SearchStep {
  kNone,  // no boundary found: held, or lost
  kPredicted,
  kUnmoved,
  kGrowth,
  kSmaller,
  kImageMotion,
  kMemory,
  kInPlace,
  kWholeFrame,
};

// "predicted", "unmoved", "growth", "smaller", "image motion", "memory", "in place",
// "whole frame", "none".
const char* step_name(SearchStep step);

// Where the grouping time of one frame went (milliseconds; a recovery search adds to each).
struct StageTimes {
  double filter_ms = 0.0;    // stage 2: distance filter (and the max_segments cap)
  double graph_ms = 0.0;     // stages 3-4: Delaunay gap filling and the graph
  double search_ms = 0.0;    // stage 5: BDSP cycle candidates
  double choice_ms = 0.0;    // stage 6: the (stabilised) choice
  double recovery_ms = 0.0;  // the motion estimate of a lost frame
};

struct TrackResult {
  Polygon boundary;                     // the tracked boundary (the previous one when held)
  bool held = false;                    // no admissible candidate: the previous boundary was kept
  bool recovered = false;               // found again where image motion moved it (after a miss)
  SearchStep step = SearchStep::kNone;  // the step of the search that found `boundary`
  // How far to trust `boundary` (confidence.h; 0 when held or lost) and what that makes of the
  // frame (track_state.h). While lost, `boundary` is the last confident one and `held` is set.
  // With the object memory, at most `visible` for a frame the memory stands in for, and for a
  // cycle taken within a second of that though most of it departs from the remembered object.
  TrackState state = TrackState::kTracking;
  double confidence = 0.0;
  BoundaryEvidence evidence;  // what the confidence was computed from (defaults when held)
  bool reacquired = false;    // the lost object was found again in this frame
  // The fraction of the remembered outline whose edge was seen where the boundary puts it
  // (object_memory.h); 1 before the memory holds an outline, 0 when held or lost.
  double visible = 1.0;
  // The boundary is the remembered outline fitted to the visible part of the object, not a cycle
  // of this frame's edges (the cycle chosen departed from the object, or none was found).
  bool from_memory = false;
  double cost = 0.0;             // grouping cost Γ of the chosen cycle (Eq. 1)
  double area_similarity = 0.0;  // Eq. 2 between the chosen cycle and the previous boundary
  int num_detected = 0;          // segments from the line detector
  int num_kept = 0;              // segments passing the distance filter (and the cap)
  int num_dropped = 0;           // segments passing the filter dropped by max_segments
  int num_vertices = 0;          // graph size
  int num_edges = 0;
  int num_candidates = 0;    // BDSP cycle candidates evaluated
  double line_ms = 0.0;      // colour conversion + line detection
  double grouping_ms = 0.0;  // filter + graph + BDSP + choice (+ recovery): the sum of `stages`
  StageTimes stages;
  double total_ms() const { return line_ms + grouping_ms; }
};

// What the last frame's grouping looked at, for drawing (paper Fig. 2).
struct TrackDebug {
  std::vector<Segment> detected;  // all detected segments
  SegmentGraph graph;             // kept segments and generated gap fillers
};

class Tracker {
 public:
  // Throws std::invalid_argument when the options are invalid.
  explicit Tracker(const TrackerOptions& options = {});
  ~Tracker();
  // A moved-from tracker may only be assigned to or destroyed.
  Tracker(Tracker&&) noexcept;
  Tracker& operator=(Tracker&&) noexcept;

  // Sets the initial boundary. Throws std::invalid_argument if the frame is empty or not 8-bit,
  // or the polygon is not a usable boundary (see check_boundary_polygon) or leaves the frame.
  void init(const cv::Mat& frame, const Polygon& polygon);
  // Initialises from a box instead of a polygon: the most salient closed boundary inside it (the
  // least-Γ cycle of the segments detected in the box, box_init.h). Returns that boundary.
  // Throws std::invalid_argument for a bad frame or box, std::runtime_error when the box holds
  // no closed boundary.
  Polygon init_from_box(const cv::Mat& frame, const cv::Rect& box);

  // Tracks the boundary into `frame` (8-bit grey, BGR or BGRA). Requires init().
  // Frames, in every call, are only read, and only during it: none is written or kept.
  TrackResult track(const cv::Mat& frame);

  bool initialized() const;
  const Polygon& boundary() const;
  const TrackerOptions& options() const;
  // Filled by track() when enabled; off by default to keep the hot path lean.
  void set_keep_debug(bool keep);
  const TrackDebug& debug() const;

  // The state and the stages (tracker_impl.h): private, so that they change without breaking
  // the ABI.
  class Impl;
  explicit Tracker(std::unique_ptr<Impl> impl);

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace scbt
