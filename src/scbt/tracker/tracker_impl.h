// The tracker's state and per-frame flow behind Tracker (tracker.h): every stage it holds by value,
// the reused buffers, and the steps of a frame. Private: its layout may change with any release.
#pragma once

#include <memory>
#include <opencv2/core/mat.hpp>
#include <optional>

#include "scbt/choice/boundary_choice.h"
#include "scbt/geometry/polygon.h"
#include "scbt/geometry/shape_descriptor.h"
#include "scbt/graph/segment_graph.h"
#include "scbt/lines/exposure.h"
#include "scbt/motion/motion_estimate.h"
#include "scbt/tracker/contrast_profile.h"
#include "scbt/tracker/cycle_stage.h"
#include "scbt/tracker/frame_checks.h"
#include "scbt/tracker/motion_model.h"
#include "scbt/tracker/object_memory.h"
#include "scbt/tracker/reacquire.h"
#include "scbt/tracker/reacquire_view_change.h"
#include "scbt/tracker/scene_keyframes.h"
#include "scbt/tracker/shape_memory.h"
#include "scbt/tracker/track_state.h"
#include "scbt/tracker/tracker.h"
#include "scbt/tracker/tracker_options.h"
#include "scbt/tracker/tracker_with_stage.h"

namespace scbt {

class Tracker::Impl {
 public:
  Impl(const TrackerOptions& options, const MakeCycleStage& make_cycle_stage);

  // As Tracker's.
  void init(const cv::Mat& frame, const Polygon& polygon);
  Polygon init_from_box(const cv::Mat& frame, const cv::Rect& box);
  TrackResult track(const cv::Mat& frame);
  bool initialized() const { return !boundary_.empty(); }
  const Polygon& boundary() const { return boundary_; }
  const TrackerOptions& options() const { return options_; }
  void set_keep_debug(bool keep) { keep_debug_ = keep; }
  const TrackDebug& debug() const { return debug_; }

 private:
  TrackerOptions options_;
  std::unique_ptr<LineDetector> detector_;
  Polygon boundary_;
  double boundary_area_ = 0.0;
  cv::Size frame_size_;
  cv::Mat gray_;
  cv::Rect gray_roi_;      // the window of the frame gray_ holds
  cv::Mat smoothed_gray_;  // gray_ smoothed for a noisy frame (AdaptiveThresholdOptions)
  // The grey window around the boundary the last time it was tracked, for re-finding it by
  // image motion when it is lost (TrackerOptions::recover_by_motion).
  cv::Mat reference_gray_;
  cv::Rect reference_roi_;
  MotionModel motion_;    // predicts where the boundary goes next (TrackerOptions::predict_motion)
  Polygon predicted_;     // where this frame's search looks (reused buffer)
  Polygon extrapolated_;  // where the boundary's last velocity puts it (place_by_image_motion)
  BoundaryAppearance appearance_;  // confirms predictions (TrackerOptions::confirm_motion)
  // A prediction needs confirming on few frames: the last tracked boundary's appearance is then
  // read from the motion reference (reference_gray_, kept anyway) rather than on every frame.
  bool appearance_pending_ = false;
  Polygon appearance_boundary_;  // the boundary whose appearance is pending (frame coordinates)

  // One pass of the per-frame pipeline searching around `prior`. Two are kept (the first try
  // and a recovery search) and reused frame to frame, so that steady-state tracking allocates
  // next to nothing.
  struct Attempt {
    cv::Rect roi;
    EdgeThresholds thresholds;  // the detector's thresholds for this attempt
    std::vector<Segment> detected;
    std::vector<Segment> kept;
    std::vector<double> kept_distances;  // the filter's, 3 per kept segment (segment_filter.h)
    int num_dropped = 0;
    SegmentGraph graph;
    std::unique_ptr<CycleStage> cycles;  // stages 5-6
    std::optional<BoundaryChoice> choice;
    double line_ms = 0.0;
    double grouping_ms = 0.0;
    StageTimes stages;
    // Filled by assess(): the chosen cycle, its evidence and confidence.
    bool assessed = false;
    Polygon boundary;
    BoundaryEvidence evidence;
    ShapeDescriptor descriptor;  // of boundary
    double confidence = 0.0;
  };
  // `adapt`: with thresholds (and smoothing) adapted to this window (retry_weak). `gate_area`
  // (when > 0): the area the gate (Eq. 2) compares candidates with instead of the prior's.
  void attempt(const cv::Mat& frame, const Polygon& prior, Attempt* a, double min_similarity,
               bool adapt = false, double gate_area = 0.0);
  // A tracking frame's search: the tracking steps of SearchStep (tracker.h) in order. Returns the
  // attempt whose boundary the frame takes (its choice empty when nothing qualified), with
  // gray_ holding its window; `result` gets the times, the step and `recovered`.
  Attempt* search(const cv::Mat& frame, TrackResult* result);
  // One frame's search as its steps see it and leave it.
  struct FrameSearch {
    TrackResult* result = nullptr;  // gets every step's times
    Attempt* found = nullptr;       // the attempt taken so far (its choice empty: nothing yet)
    SearchStep step = SearchStep::kNone;  // the step `found` came from
    double gate_area = 0.0;               // for attempt(): a sustained shrink's area, or 0
    bool retry_weak_frames = false;       // AdaptiveThresholdOptions::retry_weak_frames applies
    bool adapted_first = false;           // the frame's first search uses adapted thresholds
    bool adapted_next = false;            // ... and the next frame's (keep_retry_winner)
  };
  // What one step did: the attempt it searched (nullptr: its conditions did not hold, nothing
  // searched) and whether the frame takes that attempt's boundary (the step's test, tracker.h).
  struct StepOutcome {
    Attempt* searched = nullptr;
    bool taken = false;
  };
  // The tracking steps, one signature (tracker_search.cc).
  StepOutcome search_predicted(const cv::Mat& frame, FrameSearch* s);
  StepOutcome search_unmoved(const cv::Mat& frame, FrameSearch* s);
  StepOutcome search_growth(const cv::Mat& frame, FrameSearch* s);
  StepOutcome search_smaller(const cv::Mat& frame, FrameSearch* s);
  StepOutcome search_image_motion(const cv::Mat& frame, FrameSearch* s);
  // predicted_: where the frame's first search looks (the boundary, or where its motion puts it).
  void predict_placement(const cv::Mat& frame);
  // Attempt a's chosen cycle (if any), its evidence against `previous` and its confidence; the
  // grey window gray_ must still be a's.
  void assess(Attempt* a, const Polygon& previous) const;
  // AdaptiveThresholdOptions::retry_weak_frames: `first` (searched with s->adapted_first's
  // thresholds) or, when it was weak, the search again with the other thresholds (adapted or
  // published) around `prior` into `retry`, if that found a trusted boundary; *adapted_next then
  // becomes the retry's thresholds when AdaptiveThresholdOptions::keep_retry_winner.
  Attempt* retry_weak(const cv::Mat& frame, Attempt* first, const Polygon& prior, Attempt* retry,
                      FrameSearch* s, bool* adapted_next);
  // Whether an assessed attempt's boundary may be taken: trusted (LossOptions::tracking_confidence)
  // and, found with `adapted` thresholds, of the reference shape
  // (LossOptions::match_shape_distance).
  bool trusted(const Attempt& a, bool adapted) const;
  bool adapted_first_ = false;  // the first search of a frame uses adapted thresholds
  // This frame's exposure stretch (ExposureOptions) and published thresholds scaled to its
  // blur: what adapted thresholds start from and detection returns to.
  void scale_thresholds_to_exposure(const cv::Mat& frame);
  GreyStretch exposure_stretch_;
  // `part` of this frame (or the frame) in grey, stretched to the frame's exposure: every grey
  // window the tracker detects, measures or compares on.
  void to_exposed_gray(const cv::Mat& part, cv::Mat* gray) const;
  int gradient_threshold_;
  int anchor_threshold_;
  // The gradient threshold scaled to the exposure only (the gain the stretch leaves): a blurred
  // step keeps its height, so the smallest grey step counted as an edge (the confidence's, the
  // blur estimate's) follows this.
  int step_threshold_;
  // TrackerOptions::blur: the running estimate of the edge spread (px) of the confidently tracked
  // boundaries (< 0: none yet), which scales the thresholds (edge_blur_gain), and its update from
  // `gray` (the window at `window_tl`).
  double edge_blur_sigma_ = -1.0;
  int blur_frames_waited_ = 0;  // confidently tracked frames since the last estimate
  void measure_edge_blur(const cv::Mat& gray, cv::Point window_tl);
  // TrackerOptions::smooth_noisy_frames: `gray` smoothed into *smoothed when the camera's noise
  // (Immerkaer's estimate, refreshed every few frames) calls for it, the detector's thresholds
  // then lowered with the smoothing (*thresholds_changed set); otherwise `gray`.
  const cv::Mat& smooth_if_noisy(const cv::Mat& gray, cv::Mat* smoothed, bool* thresholds_changed);
  // The camera's noise (grey levels), estimated again on `gray` (a window of this frame) when the
  // last estimate is a few frames old.
  double camera_noise(const cv::Mat& gray);
  double noise_sigma_ = -1.0;  // grey levels; < 0: estimated on the next window
  int frames_since_noise_estimate_ = 0;
  // TrackerOptions::measure_motion: predicted_ becomes the boundary moved by the image motion
  // around it since the last tracked frame, when its recent motion says it moves
  // (tracker_predict.cc).
  void place_by_image_motion(const cv::Mat& frame);
  // Whether `moved` (a predicted placement of the boundary) agrees with its appearance better
  // than `unmoved` does, and at least by TrackerOptions::min_motion_agreement.
  bool confirmed(const cv::Mat& frame, const Polygon& moved, const Polygon& unmoved);
  // After boundary_ was tracked on `frame`: the appearance that confirms the next predictions,
  // read now, or left pending when the motion reference keeps this frame's window.
  void remember_appearance(const cv::Mat& frame);
  // Reads a pending appearance from the motion reference (before the reference moves on).
  void settle_appearance();
  // Whether remember_reference keeps the windows the image motion is measured against.
  bool keeps_motion_reference() const;
  static void add_retry_times(const Attempt& retry, TrackResult* result);
  // The evidence (confidence.h) of `chosen`, the cycle attempt `a` chose around `previous`; the
  // grey window gray_ must still be a's (tracker_lost.cc). `descriptor`, when given, gets the
  // shape_descriptor of `chosen`.
  BoundaryEvidence evidence_of(const Attempt& a, const Polygon& chosen, const Polygon& previous,
                               ShapeDescriptor* descriptor = nullptr) const;
  // Whether `left` (a boundary the object may have shrunk away from) holds fewer clear edges in
  // attempt a's window than a's chosen boundary (assessed): the object's outline left it, rather
  // than a smaller cycle inside it being found while it is still there.
  bool outline_left(const Attempt& a, const Polygon& left) const;
  // On a surprising frame after a tracked one (held, confidence below tracking, or a shape change
  // beyond a match): whether the view was cut (LossOptions::cut_correlation), told to the monitor.
  // Needs the motion reference unchanged (tracker_lost.cc).
  void check_view_cut(const cv::Mat& frame, const TrackResult& result);
  // A frame while the object is lost: its steps kInPlace, then kWholeFrame (tracker.h).
  TrackResult track_lost(const cv::Mat& frame);
  // kWholeFrame's placements of the last confident outline over the frame (its `segments`), in
  // the order they are searched. Returns how many at the end lie beyond the moderate scales.
  size_t place_over_frame(const std::vector<Segment>& segments, std::vector<Placement>* placements);
  // kWholeFrame's best match among the placements, each searched (empty: none); `result` gets
  // its evidence, cost and the search times, match_graph_ and match_kept_ its graph.
  // With `partly_seen` (the memory's fit where it sees the object partly; its outline searched
  // first), a match along that fit (along_partial_fit) counts though its shape or inside level
  // changed (the view or the light on the object changed while it was lost); elsewhere only a
  // match where the memory, fitted there, sees more of its outline counts, or, when the fit is
  // `held` from an earlier frame, any match, ranked last and marked (match_unvetted_).
  Polygon best_match(const cv::Mat& frame, const std::vector<Placement>& placements,
                     size_t beyond_count, const MemoryFit* partly_seen, bool held,
                     TrackResult* result);
  // Whether `cycle` runs along the memory's partial fit: within twice the agreement distance (its
  // hidden part is predicted, less exactly) but for kAgreeMismatch of it, either way.
  bool along_partial_fit(const Polygon& cycle, const MemoryFit& partly_seen) const;
  // The first search while lost (tracker_resume.cc): tracking's own search, with the tracking
  // bar. True (and *result filled) when the object was found there.
  bool resume_in_place(const cv::Mat& frame, TrackResult* result);
  // Tracking starts again from `boundary`, found in `frame` by either search while lost: the
  // state, the last confident boundary, the motion model and its references restart there.
  // `result` gets the state and the boundary; its evidence must already be the boundary's.
  // `vouched_by_memory`: the memory saw the object partly and vouched for the boundary (it runs
  // along the partial fit, or the memory fitted on it sees more of itself): the memory is moved
  // onto it and keeps its outline instead of restarting from it (the boundary may be cut short
  // by an occluder still in front).
  void resume_tracking_from(const cv::Mat& frame, Polygon boundary, TrackResult* result,
                            bool vouched_by_memory = false);
  // After a frame whose boundary was found by attempt `a`: its grey window becomes the motion
  // reference (TrackerOptions::recover_by_motion).
  void remember_reference(const Attempt& a);
  // The statistics (and, when kept, the debug view) of the attempt whose boundary is reported.
  void report_attempt(const Attempt& a, TrackResult* result);
  // [0] and [1]: the search where the boundary is predicted (and its threshold retry or a
  // recovery); [2] and [3]: where it was, when a prediction found nothing trusted.
  Attempt attempts_[4];
  LossMonitor monitor_;
  Reacquirer reacquirer_;
  SceneKeyframes keyframes_;     // confident views of the object's surroundings, for the search
  ViewChangeMatch view_change_;  // matches seen from another distance or angle, while lost
  cv::Mat search_gray_;          // the whole frame in grey, while lost
  cv::Mat cut_gray_;             // the motion reference's window in this frame (check_view_cut)
  TranslationEstimator translation_;  // image motion since the reference, its buffers reused
  // A cycle that matched while lost, waiting for LossOptions::confirm_frames matches in a row.
  Polygon pending_;
  // The output while lost: the boundary when the object was declared lost. boundary_ meanwhile
  // follows whatever tracking's own search finds (tracker_resume.cc).
  Polygon lost_output_;
  int pending_matches_ = 0;
  SegmentGraph match_graph_;  // the graph the best match while lost was found in
  int match_kept_ = 0;
  // The best match while lost fails a held partial fit's judgement (best_match).
  bool match_unvetted_ = false;
  StableChooser chooser_;     // its buffers and distance cache are reused frame to frame
  ShapeMemory shape_memory_;  // the shape the choice weighs candidates against
  ObjectMemory memory_;       // the object's outline and edges (TrackerOptions::object_memory)
  // The memory as it was before it last restarted (on a new view, or on a whole-frame re-find):
  // where a cycle the current memory does not agree with, or the current fit, puts the object and
  // it sees kResumeVisible of itself, more than the current memory, the restart was wrong (an
  // occluder's cut taken for a view) or the view came back, and it is the memory again.
  ObjectMemory former_memory_;
  cv::Mat memory_gray_;       // the window the memory is fitted to while lost
  cv::Point memory_gray_tl_;  // its top-left corner in the frame
  // While lost: the memory looked for where the object was last placed and around it
  // (search_memory). Tracking resumes from it when TrackerOptions::min_visible of its outline is
  // seen (kResumed, *result filled); with kPredictVisible seen the object is there, partly hidden
  // (kPartlySeen).
  enum class MemoryResume { kNotSeen, kPartlySeen, kResumed };
  // *seen: the fit (valid when the object is at least partly seen).
  MemoryResume resume_from_memory(const cv::Mat& frame, TrackResult* result, MemoryFit* seen);
  // Below this much of the outline seen (and no agreeing cycle) the memory is looked for around
  // its last place; a fit found there must see as much to move it.
  static constexpr double kResumeVisible = 0.85;
  // A cycle along the fitted outline but for at most this fraction of it agrees with the memory.
  static constexpr double kAgreeMismatch = 0.15;
  // The least visible fraction the memory's fitted outline stands in for the object with.
  static constexpr double kPredictVisible = 0.35;
  // A cycle that departs from the fitted outline yet runs along this fraction of the memory's
  // own edges is the object seen from a new view (the memory is stale, not the cycle wrong).
  static constexpr double kNewViewExplained = 0.85;
  // Frames in a row a new view must be seen in before the memory restarts on it (a sixth of a
  // second at 30 frames a second), and the count so far.
  static constexpr int kNewViewFrames = 5;
  int new_view_frames_ = 0;
  // A confident cycle along the fitted outline with this much of it visible gives the memory its
  // shape (with less, part may be hidden and cut off by the cycle: only its place and view).
  static constexpr double kReshapeVisible = 0.9;
  // A cycle taken within kPartlySeenHold frames of a stand-in, farther than the agreement
  // distance from more than this fraction of the fitted outline, is reported with the memory's
  // confidence (track()); the frames since the memory last stood in.
  static constexpr double kElsewhereMismatch = 0.5;
  int frames_since_stand_in_ = 0;
  // The fraction of the way the memory's shape moves onto such a cycle per frame: about a second
  // (30 frames) to take a new view's shape.
  static constexpr double kShapeRate = 1.0 / 30.0;
  // What this frame's fit of the memory says of attempt a's choice.
  enum class MemoryVerdict {
    kUnjudged,  // no fit: the cycle is taken and learnt from as without the memory
    kAgrees,    // along the fitted outline: taken, and the memory learns its place and view
    kNewView,   // departs, but along the memory's edges: taken, and the memory re-anchored on it
    kDeparts,   // departs along edges like the object's own: taken, not learnt from
    kStandsIn,  // none, or departs along edges the object never had: the fitted outline replaces it
  };
  MemoryVerdict judge_by_memory(Attempt* a, const MemoryFit& fit);
  // This frame's fit of the memory (searched for around when neither it nor the cycle sees the
  // object well) and its verdict on attempt a's choice.
  struct MemoryCheck {
    MemoryFit fit;
    MemoryVerdict verdict = MemoryVerdict::kUnjudged;
    // kNewView seen kNewViewFrames in a row (not a provisional memory's restart on a departure):
    // the memory it replaces is kept (former_memory_).
    bool new_view_seen = false;
  };
  MemoryCheck check_with_memory(const cv::Mat& frame, Attempt* a);
  // The former memory fitted where `outline` is in the grey window `gray` (top-left `tl`): when it
  // sees kResumeVisible of itself there, more than `current` (the memory's fit) does, it is the
  // memory again, placed there, and *back is its fit.
  bool return_to_former_memory(const Polygon& outline, const MemoryFit& current,
                               const cv::Mat& gray, cv::Point tl, MemoryFit* back);
  // What the memory learns from the confident cycle taken this frame (boundary_, found in gray_
  // at `tl`), by the check's verdict.
  void learn_from_cycle(const MemoryCheck& check, cv::Point tl);
  // Whether the attempt's cycle, within a second of the memory standing in, lies mostly away from
  // where the memory was fitted (or, with no fit, last placed): asked before the cycle moves it.
  bool departs_after_stand_in(const MemoryCheck& check, const Attempt& a) const;
  // After a frame's state is decided (not held, not lost), for a cycle taken though it departs
  // after a stand-in: the frame's confidence is lowered to `visible`.
  void doubt_departure_from_memory(TrackResult* result) const;
  // The memory fitted from places around where it was last placed, up to half the object's size
  // or kMemorySearchMax px away (ObjectMemory::search), in a window of the frame.
  // A frame whose boundary is the memory's fitted outline: its visible fraction is the frame's
  // `visible` and confidence, step kMemory.
  static void report_memory_fit(const MemoryFit& fit, TrackResult* result);
  // The fit returned is valid only when it sees `accept_visible` of the outline.
  MemoryFit search_memory(const cv::Mat& frame, double accept_visible);
  static constexpr double kMemorySearchMax = 72.0;
  // Frames after tracking resumed from a boundary found while lost during which the memory,
  // restarted from that boundary, only follows the confident cycles (restarting from each that
  // departs) and never stands in: a re-find a few pixels off (a look-alike beside the object)
  // must not be held there; half a second of tracking confirms it. The user's initial boundary
  // needs no such confirmation.
  static constexpr int kProvisionalFrames = 15;
  int memory_provisional_ = 0;
  // While lost: the memory's last fit that saw the object partly and the frames since; for
  // kPartlySeenHold frames (a second at 30 frames a second) it judges the whole frame's matches
  // (best_match's `held`).
  static constexpr int kPartlySeenHold = 30;
  MemoryFit last_partly_seen_;
  int partly_seen_age_ = 0;
  bool keep_debug_ = false;
  TrackDebug debug_;
};

}  // namespace scbt
