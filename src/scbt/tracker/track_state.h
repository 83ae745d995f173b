// Whether the object is being tracked, may be lost, or is lost: a per-frame state from the
// confidence of the tracked boundary (confidence.h), with the last confident boundary kept to
// stand in for the object while it is lost and to recognise it again (reacquire.h).
#pragma once

#include <array>
#include <string>

#include "scbt/geometry/polygon.h"
#include "scbt/geometry/shape_descriptor.h"
#include "scbt/tracker/confidence.h"
#include "scbt/tracker/reacquire_view_change.h"

namespace scbt {

enum class TrackState {
  kTracking,   // confidence >= LossOptions::tracking_confidence
  kUncertain,  // a boundary was found but is not trusted, or the object was missed (not yet lost)
  kLost,       // missed on LossOptions::misses_to_lost frames in a row; searching for it
};

std::string to_string(TrackState state);

struct LossOptions {
  // Off: the tracker never declares the object lost and never searches the frame (the paper's
  // behaviour); states are still reported (`uncertain` instead of `lost`).
  bool enabled = true;
  // A frame whose boundary has at least this confidence is `tracking`; its boundary joins the
  // confident ones the reference shape is drawn from (LossMonitor::reference). The confidence
  // falls with the change of shape from that reference, so it follows gradual change only.
  double tracking_confidence = 0.5;
  // A held frame, or a boundary of confidence below this, is a miss.
  double miss_confidence = 0.2;
  // This many misses in a row: `lost`. The output goes back to the last confident boundary.
  int misses_to_lost = 3;
  // ... or this many frames in a row without a `tracking` one (misses and low-confidence
  // boundaries): after a jump the search band can hold a wrong cycle good enough not to be a
  // miss, and following it lets its shape become the reference.
  int unsure_to_lost = 5;
  // While lost, a closed cycle is taken as the object found again when its shape_distance to the
  // last confident boundary is at most this (an ellipse of aspect 1.1 against a circle: 0.024)
  // and its confidence at least reacquire_confidence: a search over the whole frame tests many
  // more cycles than tracking does, so a look-alike passes a tracking-level bar far more often.
  double match_shape_distance = 0.05;
  double reacquire_confidence = 0.9;
  // ... and when the grey level just inside it is within this of the last confident boundary's
  // (a textureless object keeps its level; a look-alike outline in the clutter rarely does).
  double max_level_change = 30.0;
  // A match is taken once it has been found on this many frames in a row at the same place
  // (within a quarter of the object's size): one frame's look-alike is not enough.
  int confirm_frames = 2;
  // A surprising frame after a `tracking` one (held, less confident, or a shape change beyond
  // match_shape_distance) is checked for a cut of the view (a jump in the video, the camera turned
  // away): the window around the boundary, averaged down to 32 x 32, against the last tracked
  // one, best zero-mean normalised correlation over shifts of up to a fifth of the window. Below
  // this, the view was cut: blur and motion keep a coarse view alike (0.89 or more on the
  // dataset's surprising frames), a cut does not (0.41-0.68 after its 2 s jumps, 0 to grey).
  // After a cut, tracking resumes only on a boundary whose shape is within match_shape_distance
  // of the last confident one: a wrong cycle left in the band would otherwise gain confidence as
  // the reference follows it.
  double cut_correlation = 0.8;
  // Scales of the last confident boundary searched for (moderate: the object keeps its size
  // within this range while out of sight).
  double min_scale = 0.75;
  double max_scale = 1.33;
  // Places tried per frame while lost: near the last position, then over the whole frame.
  int near_tries = 2;
  int frame_tries = 3;
  // A match seen from another distance or angle (beyond the scales above, or foreshortened):
  // taken when it also looks like the object inside (reacquire_view_change.h).
  ViewChangeOptions view_change;

  // Throws std::invalid_argument naming the first bad value.
  void check() const;
};

// Turns per-frame confidences into states and remembers the last confident boundary.
class LossMonitor {
 public:
  explicit LossMonitor(const LossOptions& options = {}) : options_(options) {}

  // A new track from a boundary the user trusts.
  // `inside_level`: BoundaryEvidence::inside_level of the boundary (-1 unknown).
  void reset(const Polygon& boundary, double inside_level);
  // The state of a frame whose boundary `boundary` was found with `confidence`, or held
  // (`held`, confidence 0). Records the boundary as confident when it is. `descriptor`, when
  // given, is shape_descriptor(boundary) (measure_evidence's): not computed again. `refound`:
  // the boundary was found away from where it was searched for (Tracker's motion recovery); it
  // is `tracking` only with the last confident shape and inside level, as after a cut.
  // `vouched`: the object memory sees the boundary as the remembered object (along its fitted
  // outline, enough of it visible), which stands for that match: after an occluder has hidden the
  // object for a while the last confident shape is stale, the memory is not.
  TrackState update(const Polygon& boundary, double confidence, bool held,
                    const BoundaryEvidence& evidence, const ShapeDescriptor* descriptor = nullptr,
                    bool refound = false, bool vouched = false);
  // A frame on which the object memory placed the partly hidden object from the part of it seen
  // (Tracker's step `memory`): the object is there, so it ends a run of misses or unsure frames;
  // its boundary, partly predicted, does not become a confident one.
  void note_partly_seen() {
    misses_ = 0;
    unsure_ = 0;
  }
  // The object found again while lost: tracking resumes from `boundary`.
  void resume(const Polygon& boundary, double inside_level) { reset(boundary, inside_level); }
  // Whether a cycle found while lost is the object: its shape and inside level match the last
  // confident boundary's and its confidence is at least reacquire_confidence (a search over the
  // frame) or `min_confidence` (a search where the object was last seen, as tracking does).
  bool matches(const Polygon& cycle, const BoundaryEvidence& evidence, double confidence) const {
    return matches(cycle, evidence, confidence, options_.reacquire_confidence);
  }
  bool matches(const Polygon& cycle, const BoundaryEvidence& evidence, double confidence,
               double min_confidence) const;

  TrackState state() const { return state_; }
  // The shape searched for while lost: the boundary kLag confident frames before the loss, or the
  // reference (below) of that time when the boundary was an outlier (beyond match_shape_distance
  // of it). While tracking: the reference's boundary.
  const Polygon& last_confident() const { return last_confident_.boundary; }
  // The newest confident boundary: the output while lost (where the object was last seen).
  const Polygon& latest_confident() const { return kept_[newest()].boundary; }
  // The shape the confidence compares with (BoundaryEvidence::shape_change) and a cycle found
  // while lost must match: the confidence-weighted medoid of the last kKept confident frames.
  const ShapeDescriptor& reference() const { return last_confident_.descriptor; }
  const LossOptions& options() const { return options_; }
  // The view was cut (LossOptions::cut_correlation): until a frame is `tracking` again, its
  // boundary must match the last confident shape; if the object is lost meanwhile, where it was
  // says nothing (the search skips resuming in place) until it is found again.
  void note_view_cut() { after_cut_ = true; }
  bool after_cut() const { return after_cut_; }

 private:
  struct Confident {
    Polygon boundary;
    ShapeDescriptor descriptor;
    double level = -1.0;
    double confidence = 1.0;
  };
  // The last kKept confident frames (a ring). The reference is the one of least
  // confidence-weighted shape distance to the others: a boundary that scraped past the tracking
  // bar once (a neighbouring cycle at 0.53) is outvoted by the frames around it instead of becoming
  // what the next frames are measured against (and then confirmed by them at 1.0); a real change
  // of shape takes over once it holds for most of the kept frames.
  static constexpr int kKept = 5;
  // The frames just before a loss are suspect (an occluder may already cover part of the object
  // while the confidence is still high): the search uses the shape of kLag confident frames
  // earlier.
  static constexpr int kLag = 4;

  // The grey level just inside `evidence`'s boundary is within max_level_change of the last
  // confident one's (or either is unknown).
  bool keeps_level(const BoundaryEvidence& evidence) const;
  void add_confident(const Polygon& boundary, double inside_level, double confidence,
                     const ShapeDescriptor* descriptor = nullptr);
  int newest() const { return (kept_next_ + kKept - 1) % kKept; }

  LossOptions options_;
  TrackState state_ = TrackState::kTracking;
  int misses_ = 0;
  int unsure_ = 0;  // frames in a row that were not `tracking`
  bool after_cut_ = false;
  std::array<Confident, kKept> kept_;
  double distance_[kKept][kKept] = {};  // shape distances between the kept frames
  int kept_size_ = 0;
  int kept_next_ = 0;
  Confident last_confident_;  // the reference, or while lost the one kLag frames back
  std::array<Confident, kLag> past_references_;  // a ring: the shapes to search for, per frame
  int past_size_ = 0;
  int past_next_ = 0;
};

}  // namespace scbt
