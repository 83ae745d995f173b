// The body of `scbt demo --depth`: an RGB-D clip of a bowl rendered in code (colour frames and
// 16-bit depth with a real sensor's edge artefacts: noise, mixed pixels, holes), tracked from its
// known first outline, every tracked boundary lifted to 3-D with that frame's depth and scored
// against the bowl's known rim (centroid, normal, radius). The clip is written as `scbt track
// --depth` reads it, with the command that tracks it.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>

#include "scbt/tracker/tracker_options.h"

namespace scbt {

struct DepthDemoOptions {
  std::string out_dir = "scbt-demo-depth";  // created if missing
  int frames = 30;                          // clip length, the initial frame included
  double distance = 0.7;                    // the rim's distance from the camera at the start (m)
  std::uint32_t seed = 1;                   // the sensor's noise, mixed pixels and holes
  bool quiet = false;                       // no progress bar
  TrackerOptions tracker;

  // Throws std::invalid_argument naming the first bad value.
  void check() const;
};

// Errors of one clip: means and worst over the frames whose lift was valid.
struct DepthDemoSummary {
  int frames = 0;
  int valid = 0;                  // frames whose lift was valid with a circle found
  double centroid_mean_mm = 0.0;  // |centroid - true centre|
  double centroid_max_mm = 0.0;
  double centroid_z_mean_mm = 0.0;  // signed, along the optical axis (+ = too far)
  double normal_mean_deg = 0.0;
  double normal_max_deg = 0.0;
  double radius_mean_percent = 0.0;  // |radius / true radius - 1|
  double radius_max_percent = 0.0;
  double outline_mean_px = 0.0;  // tracked vs true outline (mean boundary distance)
  std::string colour_dir;        // out_dir/colour/NNNN.png
  std::string depth_dir;         // out_dir/depth/NNNN.png, 16-bit millimetres
  std::string init_path;         // out_dir/init.txt: the true first outline
  std::string truth_path;        // out_dir/truth3d.csv: frame,x,y,z,nx,ny,nz,radius (metres)
  std::string points3d_path;     // out_dir/points3d.csv: the demo's lifts, as --points3d
  std::string intrinsics;        // "fx,fy,cx,cy"
  std::string track_command;     // the `scbt track --depth` command for this clip
};

// Runs the demo. Progress goes to `log` unless quiet. Text outputs appear only when complete.
DepthDemoSummary run_depth_demo(const DepthDemoOptions& options, std::ostream& log);

// The summary as a short human-readable block, ending with the track command.
std::string format_depth_demo_summary(const DepthDemoSummary& summary);

}  // namespace scbt
