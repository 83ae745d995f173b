// Synthetic scenes in which the object disappears for a while and comes back: an occluder passing
// over it, the object leaving the frame and returning elsewhere, blank frames. The ground truth of
// the loss handling tests (tracker/track_state.h) and of the confidence calibration.
#pragma once

#include <string>
#include <vector>

#include "scbt/synthetic/scene.h"

namespace scbt {

enum class GapKind {
  kOccluder,  // a flat rectangle slides over the object, covers it, slides off
  kExit,      // the object moves out of the frame and comes back somewhere else
  kBlank,     // the frames are replaced by one uniform grey
};

// Parses "occluder", "exit" or "blank"; throws std::invalid_argument otherwise.
GapKind parse_gap_kind(const std::string& name);
std::string to_string(GapKind kind);

struct GapSceneOptions {
  GapKind kind = GapKind::kOccluder;
  int frames_before = 15;  // visible frames before the gap (the first is the initial frame)
  int gap = 20;            // frames in which the object is wholly hidden
  int frames_after = 20;   // visible frames after it
  // The object drifts by this per frame (pixels) in a direction drawn from the seed.
  double drift = 1.0;

  // Throws std::invalid_argument naming the first bad value.
  void check() const;
};

struct GapScene {
  std::vector<SceneFrame> frames;
  // Per frame: none of the object can be seen / part of it is hidden (an occluder coming or going,
  // the object crossing the frame's edge).
  std::vector<bool> hidden;
  std::vector<bool> partly_hidden;
  int first_back = 0;  // the first frame after the gap in which the whole object is visible again
};

// Frames: frames_before visible, then the object goes (partly hidden frames for an occluder or an
// exit), `gap` wholly hidden frames, the object comes back (partly hidden frames again for an
// occluder), then frames_after visible ones. Deterministic per (scene options, gap options).
GapScene render_gap_scene(const SceneOptions& scene, const GapSceneOptions& options);

}  // namespace scbt
