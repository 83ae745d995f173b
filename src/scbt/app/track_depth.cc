#include "scbt/app/track_depth.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "scbt/depth/boundary_3d_io.h"
#include "scbt/depth/camera_info.h"
#include "scbt/render/rim_overlay.h"

namespace scbt {

void TrackDepthOptions::check() const {
  if (!enabled()) {
    if (!points3d.empty() || !boundary3d.empty() || !intrinsics.empty() || !camera_info.empty()) {
      throw std::invalid_argument(
          "--points3d, --boundary3d, --intrinsics and --camera-info need --depth DEPTH_INPUT");
    }
    return;
  }
  if (points3d.empty()) {
    throw std::invalid_argument("--depth needs --points3d OUT.csv (the per-frame 3-D results)");
  }
  if (intrinsics.empty() == camera_info.empty()) {
    throw std::invalid_argument(
        "--depth needs the camera: give exactly one of --intrinsics fx,fy,cx,cy or "
        "--camera-info FILE");
  }
  if (!intrinsics.empty()) {
    try {
      parse_intrinsics(intrinsics);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("--intrinsics: " + std::string(e.what()));
    }
  }
  try {
    lift.check();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("--depth-scale: " + std::string(e.what()));
  }
  // A 16-bit depth image holds 1..65535 units (0: no depth): at least some of them must be a
  // valid depth, or every frame would be lifted from nothing.
  const double nearest = 1.0 * lift.depth_scale;
  const double farthest = 65535.0 * lift.depth_scale;
  if (nearest > lift.max_depth || farthest < lift.min_depth) {
    char text[320];
    std::snprintf(text, sizeof(text),
                  "--depth-scale %g: a 16-bit depth image's values 1..65535 would be %g..%g m, "
                  "none of them within the valid depths %g..%g m (e.g. 0.001 for millimetres)",
                  lift.depth_scale, nearest, farthest, lift.min_depth, lift.max_depth);
    throw std::invalid_argument(text);
  }
}

void add_depth_paths(const TrackDepthOptions& options, std::vector<NamedPath>* inputs,
                     std::vector<NamedPath>* outputs) {
  if (!options.enabled()) return;
  inputs->push_back({"--depth", options.depth});
  if (!options.camera_info.empty()) inputs->push_back({"--camera-info", options.camera_info});
  outputs->push_back({"--points3d", options.points3d});
  if (!options.boundary3d.empty()) outputs->push_back({"--boundary3d", options.boundary3d});
}

DepthTrackOutput::DepthTrackOutput(const TrackDepthOptions& options, OutputSet* outputs)
    : options_(options) {
  camera_ = options.camera_info.empty() ? parse_intrinsics(options.intrinsics)
                                        : read_camera_info(options.camera_info);
  source_ = std::make_unique<DepthSource>(options.depth);
  points3d_ = &outputs->add_file(options.points3d);
  write_points3d_header(points3d_->stream());
  if (!options.boundary3d.empty()) boundary3d_ = &outputs->add_file(options.boundary3d);
}

std::unique_ptr<FrameSource> open_colour_source(const std::string& input,
                                                const TrackDepthOptions& options) {
  if (!options.enabled() || !is_tum_rgbd_folder(options.depth)) return open_frame_source(input);
  std::error_code error;
  if (!std::filesystem::equivalent(input, options.depth, error)) {
    throw std::invalid_argument("--depth " + options.depth +
                                " is a TUM RGB-D folder: INPUT must be that folder too (its "
                                "colour frames are rgb.txt's), got " +
                                input);
  }
  return open_image_list_source(DepthSource(options.depth).colour_files());
}

const Boundary3d& DepthTrackOutput::write(int number, const TrackResult* result,
                                          const cv::Size& frame_size) {
  last_ = Boundary3d();
  // While lost the boundary is the last confident one, not the object: no 3-D output.
  if (result != nullptr && result->state != TrackState::kLost) {
    if (number > source_->size()) {
      throw std::runtime_error(options_.depth + " has depth for " +
                               std::to_string(source_->size()) + " frame(s), none for frame " +
                               std::to_string(number));
    }
    const cv::Mat depth = source_->read(number - 1);  // empty: no depth for this frame
    if (!depth.empty() && depth.size() != frame_size) {
      throw std::runtime_error(options_.depth + ": the depth image of frame " +
                               std::to_string(number) + " is " + std::to_string(depth.cols) + "x" +
                               std::to_string(depth.rows) + ", the colour frame " +
                               std::to_string(frame_size.width) + "x" +
                               std::to_string(frame_size.height) + " (they must be aligned)");
    }
    if (!depth.empty()) {
      last_ = lift_boundary_to_3d(result->boundary, depth, camera_, options_.lift);
    }
  }
  write_points3d_row(points3d_->stream(), number, last_);
  if (boundary3d_) boundary3d_->stream() << format_boundary3d_line(last_) << '\n';
  return last_;
}

void DepthTrackOutput::draw(cv::Mat* image) const { draw_rim_3d(image, last_, camera_); }

}  // namespace scbt
