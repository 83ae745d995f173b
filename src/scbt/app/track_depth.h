// The 3-D part of `scbt track --depth` (issue 20, docs/depth.md): every frame's boundary is
// lifted with its aligned depth image (depth/boundary_3d.h), written as a row of --points3d and
// a line of --boundary3d, and drawn over the annotated frame (projected centroid and normal).
#pragma once

#include <memory>
#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

#include "scbt/depth/boundary_3d.h"
#include "scbt/depth/depth_options.h"
#include "scbt/depth/pinhole_camera.h"
#include "scbt/io/depth_source.h"
#include "scbt/io/frame_source.h"
#include "scbt/io/output_set.h"
#include "scbt/io/same_file.h"
#include "scbt/tracker/tracker.h"

namespace scbt {

struct TrackDepthOptions {
  std::string depth;        // DEPTH_INPUT: folder of numbered 16-bit PNGs, or a TUM RGB-D folder
  std::string intrinsics;   // "fx,fy,cx,cy"
  std::string camera_info;  // or a ROS camera_info YAML / OpenCV calibration file
  std::string points3d;     // per-frame CSV (required with depth)
  std::string boundary3d;   // optional: each frame's 3-D points on one line
  DepthOptions lift;        // depth_scale (--depth-scale) and the lift's thresholds

  bool enabled() const { return !depth.empty(); }
  // Throws std::invalid_argument naming the missing or conflicting option (no file access).
  void check() const;
};

// Lifts each frame's boundary and writes the 3-D outputs. Construct after the other outputs
// were added to `outputs` and before the first frame.
class DepthTrackOutput {
 public:
  // Opens the depth input and reads the intrinsics (throws std::runtime_error naming the file);
  // adds --points3d / --boundary3d to `outputs`.
  DepthTrackOutput(const TrackDepthOptions& options, OutputSet* outputs);

  // Frame `number` (1-based in the input) with boundary `result`: lifted with that frame's depth
  // unless the object is lost or the frame bad (`result` null), which give an invalid row.
  // Throws std::runtime_error when the frame has no depth image in a numbered folder or one of
  // another size than the colour frame. Returns the lift (for draw()).
  const Boundary3d& write(int number, const TrackResult* result, const cv::Size& frame_size);
  // The last lift drawn onto an annotated frame.
  void draw(cv::Mat* image) const;

 private:
  TrackDepthOptions options_;
  PinholeIntrinsics camera_;
  std::unique_ptr<DepthSource> source_;
  OutputFile* points3d_ = nullptr;
  OutputFile* boundary3d_ = nullptr;
  Boundary3d last_;
};

// The colour frames: INPUT, or with a TUM RGB-D --depth folder rgb.txt's list of that folder
// (INPUT must then name the same folder; std::invalid_argument otherwise).
std::unique_ptr<FrameSource> open_colour_source(const std::string& input,
                                                const TrackDepthOptions& options);

// The --depth input and 3-D outputs for the same-file checks (check_no_overwrite).
void add_depth_paths(const TrackDepthOptions& options, std::vector<NamedPath>* inputs,
                     std::vector<NamedPath>* outputs);

}  // namespace scbt
