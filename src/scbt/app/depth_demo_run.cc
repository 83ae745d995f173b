#include "scbt/app/depth_demo_run.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

#include "scbt/app/progress.h"
#include "scbt/depth/boundary_3d.h"
#include "scbt/depth/boundary_3d_io.h"
#include "scbt/geometry/polygon_io.h"
#include "scbt/io/output_file.h"
#include "scbt/synthetic/rgbd_scene.h"
#include "scbt/synthetic/rgbd_sensor.h"
#include "scbt/synthetic/scene.h"
#include "scbt/tracker/tracker.h"

namespace scbt {
namespace fs = std::filesystem;
namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;

std::string number_name(int number) {
  char name[32];
  std::snprintf(name, sizeof name, "%04d.png", number);
  return name;
}

// The bowl's path: it drifts 4 cm sideways and 2 cm away (scaled with the distance), its rim
// normal 36-44 degrees off the direction to the camera, turning a little about it.
std::vector<RimPose> demo_path(const DepthDemoOptions& options) {
  RimPathOptions path;
  const double scale = options.distance / 0.7;
  path.start = {-0.02 * scale, 0.0, options.distance};
  path.end = {0.02 * scale, 0.01 * scale, options.distance + 0.02 * scale};
  path.sway = 0.004 * scale;
  path.tilt_min = 36.0 * kDegree;
  path.tilt_max = 44.0 * kDegree;
  return rim_path(path, options.frames);
}

std::string shell_word(const std::string& path) {
  return path.find_first_of(" '\"\\$`") == std::string::npos ? path : "'" + path + "'";
}

}  // namespace

void DepthDemoOptions::check() const {
  if (out_dir.empty()) throw std::invalid_argument("out_dir must not be empty");
  if (frames < 2 || frames > 10000) {
    throw std::invalid_argument("frames must be in 2..10000, got " + std::to_string(frames));
  }
  if (!(distance >= 0.4 && distance <= 2.0)) {
    throw std::invalid_argument("distance must be in 0.4..2.0 m, got " + std::to_string(distance));
  }
  tracker.check();
}

DepthDemoSummary run_depth_demo(const DepthDemoOptions& options, std::ostream& log) {
  options.check();
  const RgbdSceneOptions scene;  // a bowl, 10 cm rim radius, 640x480, fx = fy = 525
  const DepthSensorOptions sensor = edge_artefact_sensor(options.seed);
  const std::vector<RimPose> poses = demo_path(options);
  const fs::path dir(options.out_dir);
  DepthDemoSummary s;
  s.colour_dir = (dir / "colour").string();
  s.depth_dir = (dir / "depth").string();
  s.init_path = (dir / "init.txt").string();
  s.truth_path = (dir / "truth3d.csv").string();
  s.points3d_path = (dir / "points3d.csv").string();
  fs::create_directories(s.colour_dir);
  fs::create_directories(s.depth_dir);
  char intrinsics[96];
  std::snprintf(intrinsics, sizeof intrinsics, "%g,%g,%g,%g", scene.camera.fx, scene.camera.fy,
                scene.camera.cx, scene.camera.cy);
  s.intrinsics = intrinsics;

  OutputFile init(s.init_path), truth(s.truth_path), points3d(s.points3d_path);
  truth.stream() << "frame,x,y,z,nx,ny,nz,radius\n";
  write_points3d_header(points3d.stream());
  Tracker tracker(options.tracker);
  ProgressBar progress(log, "demo --depth", options.frames, !options.quiet);
  double outline_sum = 0.0, centroid_sum = 0.0, centroid_z_sum = 0.0, normal_sum = 0.0,
         radius_sum = 0.0;
  for (int i = 0; i < options.frames; ++i) {
    const int number = i + 1;
    const RgbdFrame frame = render_rgbd_frame(scene, poses[i], i);
    const cv::Mat depth = apply_depth_sensor(frame.clean_depth, frame.truth, sensor, i);
    if (!cv::imwrite((dir / "colour" / number_name(number)).string(), frame.colour) ||
        !cv::imwrite((dir / "depth" / number_name(number)).string(), depth)) {
      throw std::runtime_error("cannot write the clip's frame " + std::to_string(number) + " in " +
                               options.out_dir);
    }
    char row[256];
    std::snprintf(row, sizeof row, "%d,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f\n", number,
                  frame.centre.x(), frame.centre.y(), frame.centre.z(), frame.normal.x(),
                  frame.normal.y(), frame.normal.z(), frame.radius);
    truth.stream() << row;
    // Tracked as `scbt track` does: from init.txt's outline (as written, two decimals); no
    // 3-D result while the object is lost.
    Polygon boundary;
    bool lost = false;
    if (i == 0) {
      const std::string line = format_polygon_line(frame.truth);
      init.stream() << line << '\n';
      boundary = parse_polygon_line(line);
      tracker.init(frame.colour, boundary);
    } else {
      const TrackResult result = tracker.track(frame.colour);
      boundary = result.boundary;
      lost = result.state == TrackState::kLost;
    }
    const Boundary3d rim = lost ? Boundary3d() : lift_boundary_to_3d(boundary, depth, scene.camera);
    write_points3d_row(points3d.stream(), number, rim);
    outline_sum += mean_boundary_distance(boundary, frame.truth);
    ++s.frames;
    progress.update(number);
    if (!rim.valid || !rim.circle.found) continue;
    ++s.valid;
    const Eigen::Vector3d error = 1000.0 * (rim.centroid - frame.centre);
    const double normal = std::acos(std::clamp(rim.normal.dot(frame.normal), -1.0, 1.0)) / kDegree;
    const double radius = 100.0 * std::abs(rim.circle.radius / frame.radius - 1.0);
    centroid_sum += error.norm();
    centroid_z_sum += error.z();
    normal_sum += normal;
    radius_sum += radius;
    s.centroid_max_mm = std::max(s.centroid_max_mm, error.norm());
    s.normal_max_deg = std::max(s.normal_max_deg, normal);
    s.radius_max_percent = std::max(s.radius_max_percent, radius);
  }
  progress.finish(s.frames);
  init.commit();
  truth.commit();
  points3d.commit();
  s.outline_mean_px = outline_sum / s.frames;
  if (s.valid > 0) {
    s.centroid_mean_mm = centroid_sum / s.valid;
    s.centroid_z_mean_mm = centroid_z_sum / s.valid;
    s.normal_mean_deg = normal_sum / s.valid;
    s.radius_mean_percent = radius_sum / s.valid;
  }
  s.track_command = "scbt track " + shell_word(s.colour_dir) + " --init " +
                    shell_word(s.init_path) + " -o " + shell_word((dir / "results.txt").string()) +
                    " --depth " + shell_word(s.depth_dir) + " --intrinsics " + s.intrinsics +
                    " --points3d " + shell_word((dir / "tracked3d.csv").string());
  return s;
}

std::string format_depth_demo_summary(const DepthDemoSummary& s) {
  char text[1024];
  std::snprintf(
      text, sizeof text,
      "frames %d, 3-D rim valid in %d; tracked outline %.2f px from the truth (mean)\n"
      "rim in 3-D vs truth (mean / worst): centroid %.2f / %.2f mm (along the optical axis "
      "%+.2f mm), normal %.2f / %.2f deg, radius %.2f / %.2f %%\n"
      "colour  %s\ndepth   %s (16-bit PNG, millimetres)\ninit    %s\ntruth   %s\n"
      "3-D     %s\ntrack it:\n  %s\n",
      s.frames, s.valid, s.outline_mean_px, s.centroid_mean_mm, s.centroid_max_mm,
      s.centroid_z_mean_mm, s.normal_mean_deg, s.normal_max_deg, s.radius_mean_percent,
      s.radius_max_percent, s.colour_dir.c_str(), s.depth_dir.c_str(), s.init_path.c_str(),
      s.truth_path.c_str(), s.points3d_path.c_str(), s.track_command.c_str());
  return text;
}

}  // namespace scbt
