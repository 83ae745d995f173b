// The body of `scbt demo`, the built-in default input: render a synthetic clip in code (a
// textureless outline moving, rotating and scaling over clutter and noise), track it from its
// known first outline, write the annotated clip and results, and score them against the truth.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "scbt/synthetic/scene.h"
#include "scbt/tracker/tracker_options.h"

namespace scbt {

struct DemoOptions {
  std::string out_dir = "scbt-demo";  // created if missing
  int frames = 150;                   // clip length, the initial frame included
  SceneOptions scene;                 // shape, seed, clutter, noise (640x480 by default)
  MotionOptions motion;  // start pose (centred in the frame by default) and swing of the path
  bool video = true;     // write out_dir/demo.avi
  bool quiet = false;    // no progress bar
  TrackerOptions tracker;

  // Throws std::invalid_argument naming the first bad value.
  void check() const;
};

struct DemoSummary {
  int frames = 0;  // the initial frame included
  int tracked = 0;
  int held = 0;
  // Per tracked frame: symmetric mean distance between the tracked and the true outline (px).
  std::vector<double> errors;
  double mean_error = 0.0;
  double max_error = 0.0;
  int worst_frame = 0;           // 1-based frame of max_error
  double share_under_2px = 0.0;  // of tracked frames
  double mean_ms = 0.0;          // tracking time per frame (line detection + grouping)
  double fps = 0.0;              // tracked frames per second of tracking time
  std::string results_path;      // out_dir/results.txt: line k = frame k, as `scbt track`
  std::string truth_path;        // out_dir/truth.txt, same format
  std::string errors_path;       // out_dir/errors.csv: per-frame error, held flag, timings
  std::string video_path;        // out_dir/demo.avi (empty when not written)
};

// Runs the demo. Progress goes to `log` unless quiet. Output files appear only when complete.
DemoSummary run_demo(const DemoOptions& options, std::ostream& log);

// The summary as a short human-readable block.
std::string format_demo_summary(const DemoSummary& summary);

}  // namespace scbt
