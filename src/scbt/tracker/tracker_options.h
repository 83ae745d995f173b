// Options of the boundary tracker. Defaults are the paper's values. The ones a user tunes are
// listed, with their ranges, in option_table.h (the CLI, Python, ROS and config files set them by
// name); the rest are fitted constants and internal switches.
#pragma once

#include "scbt/cycles/bdsp.h"
#include "scbt/lines/adaptive_thresholds.h"
#include "scbt/lines/edge_blur.h"
#include "scbt/lines/exposure.h"
#include "scbt/lines/line_detector.h"
#include "scbt/tracker/confidence.h"
#include "scbt/tracker/contrast_profile.h"
#include "scbt/tracker/object_memory.h"
#include "scbt/tracker/track_state.h"

namespace scbt {

struct TrackerOptions {
  LineDetectorOptions detector;
  // A segment is kept when the mean distance of its endpoints and midpoint to the previous
  // boundary is below this (pixels; §III-A: 20).
  double filter_distance = 20.0;
  // A candidate must have area similarity (Eq. 2) above this to be chosen (§II: 0.9).
  double min_area_similarity = 0.9;
  // Candidates within (1 + cost_tolerance) of the least cost Γ count as tied; the one closest to
  // the previous boundary wins (choose_boundary_stable). 0 is the paper's rule. 0.1 stops the
  // outward ratchet (inner -> outer rim -> table edges) that Γ alone allows.
  double cost_tolerance = 0.1;
  // Candidates are ranked by Γ / S^k, S their area similarity to the previous boundary (Eq. 2),
  // k this exponent (StableChooser); 0 is the paper's rule. Γ alone favours a larger cycle for
  // its area, and a cycle creeping outward inside the gate (a rim blurred, compressed or seen at
  // a low frame rate taking in some of the background) wins frame after frame. Not while lost.
  double similarity_exponent = 0.5;
  // Candidates are also ranked by exp(w d), w this weight and d their affine shape's distance to
  // the one remembered over the confident frames beyond the descriptor's jitter (ShapeMemory,
  // RankingWeights::shape_noise); 0 is off. A rim
  // whose edge fades against a background of its colour (blur, low contrast) leaks into that
  // background a little each frame, too little to notice against the frame before; the outline's
  // shape drifts from what it was while the object's own hardly changes. Not while lost.
  double shape_weight = 4.0;
  // When no candidate qualifies, estimate the image motion around the boundary since it was last
  // tracked (phase correlation) and search again where it moved, instead of holding it in place.
  bool recover_by_motion = true;
  // Search around where the boundary's motion predicts it, rather than where it was in the last
  // frame (docs/robustness-to-camera.md: at low frame rates and when the camera swings).
  bool predict_motion = true;
  // ... that motion being the image motion around the boundary since the last tracked frame
  // (phase correlation), not the boundary's last displacement extrapolated (false), which is
  // noise when a noisy or blurred frame's chosen cycle jumped. Measured (~1 ms) only on frames
  // where the extrapolation moves the boundary by at least min_predicted_move x filter_distance,
  // and followed only when the image moved that far too: slower motion stays well inside the
  // search band.
  bool measure_motion = true;
  // When the search where the boundary is predicted finds nothing trusted, search where it was as
  // well; its boundary is taken when trusted and of the reference shape (a wrong prediction then
  // costs a search, not the object).
  bool fall_back_unmoved = true;
  // With predict_motion: when the boundary's last three growth rates all shrink it, the area
  // gate (Eq. 2) compares candidates with its area shrunk at the slowest of them, so that an
  // object receding steadily at a low frame rate is not gated out; and when nothing passes the
  // gate, one gate step smaller is searched (its boundary kept only with the reference shape and
  // inside level, and where the outline it shrank from lost its edges).
  bool gate_sustained_shrink = true;
  double min_predicted_move = 0.25;
  // An extrapolated placement (and the growth-scaled retry) is searched only where the image
  // confirms it: its contrast profile (contrast_profile.h) must agree with the last tracked
  // boundary's better than the unmoved (unscaled) placement's does.
  bool confirm_motion = true;
  double min_motion_agreement = 0.0;  // ... and the predicted placement's own agreement (cosine)
  ContrastProfileOptions appearance;
  // The grey levels of a frame of low contrast (dim or washed out) stretched to half the 8-bit
  // range before detection, as an automatic gain would, as far as nothing saturates (exposure.h).
  ExposureOptions exposure;
  // EDLines thresholds scaled down by the edge spread of the last confidently tracked boundary
  // (edge_blur.h): a defocused, smoothed or motion-blurred camera lowers every edge's gradient,
  // the faint edges of a plain object first.
  EdgeBlurOptions blur;
  // A noisy camera's window is smoothed before detection as the weak-frame retry smooths it
  // (AdaptiveThresholdOptions::smooth_noise, smoothed_noise), on every frame: noise ridges
  // otherwise break the boundary into fragments that close neighbouring cycles. A window whose
  // noise calls for less than 0.5 px of smoothing (every clean dataset frame) is left as it is.
  bool smooth_noisy_frames = true;
  // Per-frame EDLines thresholds from the boundary's contrast and the image noise (edlines only).
  AdaptiveThresholdOptions adaptive_thresholds;
  BdspOptions bdsp;
  // Bound on the work per frame: when more segments than this pass the distance filter, only the
  // longest are kept (TrackResult::num_dropped counts the rest). BDSP grows about quadratically.
  int max_segments = 1500;
  // How the confidence of each frame's boundary is computed, and when the object counts as lost
  // and is searched for (docs/loss-handling.md).
  ConfidenceModel confidence;
  LossOptions loss;
  // The object's outline remembered from confident frames (object_memory.h) and fitted to each
  // frame: a chosen cycle that departs from the fitted outline along part of it (an occluder's
  // side, a background sheet taken in) is replaced by the fitted outline, whose hidden part is
  // predicted from the visible one; TrackResult::visible says how much of it was seen.
  bool object_memory = false;
  ObjectMemoryOptions memory;
  // A boundary fitted from the memory with less than this fraction of its outline visible is
  // reported `uncertain`.
  double min_visible = 0.6;

  // Throws std::invalid_argument naming the first bad value, or a switch that would do nothing:
  // measure_motion, confirm_motion, fall_back_unmoved and gate_sustained_shrink act only with
  // predict_motion (setting "predict_motion" through the option table sets them with it), and
  // smooth_noisy_frames and adaptive_thresholds.retry_weak_frames only with
  // adaptive_thresholds.enabled off.
  void check() const;
};

}  // namespace scbt
