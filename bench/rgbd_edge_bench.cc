// The rim's 3-D accuracy on a depth sensor's edges: a bowl rendered along a short path (rim
// normal 36-44 degrees off the direction to the camera) at several distances, its depth passed
// through the sensor with and without mixed (flying) pixels and blob holes (rgbd_sensor.h's
// edge_artefact_sensor), over several seeds. The boundary is the tracked one (scbt::Tracker
// from the true first outline, colour frames of seed 1) or, with --truth, the true outline.
// Prints one markdown row per condition: centroid error (mean norm and mean signed component
// along the optical axis, mm), normal error (degrees), radius error (%), each a mean over every
// seed and frame, and in brackets the range of the per-seed means.
//
//   scbt_rgbd_edge_bench [--truth] [--seeds N] [--frames N] [--distances 0.6,1.5]
//                        [--band N] [--weight-max W]
// --band and --weight-max override the sensor's mixed_pixel_band (2) and mixed_weight_max (0.5).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "scbt/depth/boundary_3d.h"
#include "scbt/synthetic/rgbd_scene.h"
#include "scbt/synthetic/rgbd_sensor.h"
#include "scbt/tracker/tracker.h"

namespace scbt {
namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;

struct Stat {
  std::vector<double> all;
  std::vector<double> per_seed;
  void add_seed(const std::vector<double>& values) {
    double sum = 0.0;
    for (double v : values) sum += v, all.push_back(v);
    per_seed.push_back(values.empty() ? NAN : sum / values.size());
  }
  std::string format(int precision) const {
    double sum = 0.0;
    for (double v : all) sum += v;
    const auto [lo, hi] = std::minmax_element(per_seed.begin(), per_seed.end());
    char text[96];
    std::snprintf(text, sizeof text, "%.*f [%.*f, %.*f]", precision, sum / all.size(), precision,
                  *lo, precision, *hi);
    return text;
  }
};

struct Clip {
  std::vector<RgbdFrame> frames;
  std::vector<Polygon> boundaries;
};

Clip render_clip(const RgbdSceneOptions& scene, double distance, int frames, bool tracked) {
  RimPathOptions path;
  path.start = {-0.02, 0.0, distance};
  path.end = {0.02, 0.01, distance + 0.02 * distance / 0.6};
  path.sway = 0.004;
  path.tilt_min = 36.0 * kDegree;
  path.tilt_max = 44.0 * kDegree;
  Clip clip;
  Tracker tracker{TrackerOptions{}};
  const std::vector<RimPose> poses = rim_path(path, frames);
  for (int i = 0; i < frames; ++i) {
    clip.frames.push_back(render_rgbd_frame(scene, poses[i], i));
    const RgbdFrame& frame = clip.frames.back();
    if (!tracked || i == 0) {
      if (tracked) tracker.init(frame.colour, frame.truth);
      clip.boundaries.push_back(frame.truth);
    } else {
      clip.boundaries.push_back(tracker.track(frame.colour).boundary);
    }
  }
  return clip;
}

std::vector<double> parse_list(const std::string& text) {
  std::vector<double> values;
  std::stringstream stream(text);
  for (std::string item; std::getline(stream, item, ',');) values.push_back(std::stod(item));
  return values;
}

int run(int argc, char** argv) {
  bool tracked = true;
  int seeds = 5, frames = 8, band = 2;
  double weight_max = 0.5;
  std::vector<double> distances = {0.6, 0.7, 1.0, 1.5};
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--truth") {
      tracked = false;
    } else if (arg == "--seeds" && i + 1 < argc) {
      seeds = std::atoi(argv[++i]);
    } else if (arg == "--frames" && i + 1 < argc) {
      frames = std::atoi(argv[++i]);
    } else if (arg == "--band" && i + 1 < argc) {
      band = std::atoi(argv[++i]);
    } else if (arg == "--weight-max" && i + 1 < argc) {
      weight_max = std::atof(argv[++i]);
    } else if (arg == "--distances" && i + 1 < argc) {
      distances = parse_list(argv[++i]);
    } else {
      std::fprintf(stderr,
                   "usage: scbt_rgbd_edge_bench [--truth] [--seeds N] [--frames N] "
                   "[--distances d1,d2,...] [--band N] [--weight-max W]\n");
      return 2;
    }
  }
  if (seeds < 1 || frames < 2) return 2;
  std::printf(
      "%s outline, %d seeds x %d frames per row, mixed pixels %d px deep with w <= %.2f; mean "
      "[range of the per-seed means]\n\n",
      tracked ? "tracked" : "true", seeds, frames, band, weight_max);
  std::printf(
      "| distance | mixed pixels | holes | centroid mm | along the optical axis mm | normal deg | "
      "radius %% | invalid |\n|---|---|---|---|---|---|---|---|\n");
  RgbdSceneOptions scene;
  for (double distance : distances) {
    const Clip clip = render_clip(scene, distance, frames, tracked);
    for (int variant = 0; variant < 4; ++variant) {
      const bool mixed = variant & 1, holes = variant & 2;
      Stat centroid, along, normal, radius;
      int invalid = 0;
      for (int seed = 1; seed <= seeds; ++seed) {
        DepthSensorOptions sensor = edge_artefact_sensor(static_cast<std::uint32_t>(seed));
        sensor.mixed_pixel_band = band;
        sensor.mixed_weight_max = weight_max;
        if (!mixed) sensor.mixed_pixel_share = 0.0;
        if (!holes) sensor.hole_share = 0.0;
        std::vector<double> c, a, n, r;
        for (int i = 0; i < frames; ++i) {
          const RgbdFrame& frame = clip.frames[i];
          const cv::Mat depth = apply_depth_sensor(frame.clean_depth, frame.truth, sensor, i);
          const Boundary3d rim = lift_boundary_to_3d(clip.boundaries[i], depth, scene.camera);
          if (!rim.valid || !rim.circle.found) {
            ++invalid;
            continue;
          }
          const Eigen::Vector3d error = rim.centroid - frame.centre;
          c.push_back(1000.0 * error.norm());
          a.push_back(1000.0 * error.z());
          n.push_back(std::acos(std::clamp(rim.normal.dot(frame.normal), -1.0, 1.0)) / kDegree);
          r.push_back(100.0 * std::abs(rim.circle.radius / frame.radius - 1.0));
        }
        centroid.add_seed(c), along.add_seed(a), normal.add_seed(n), radius.add_seed(r);
      }
      std::printf("| %.1f m | %s | %s | %s | %s | %s | %s | %d |\n", distance, mixed ? "yes" : "no",
                  holes ? "10 %" : "no", centroid.format(2).c_str(), along.format(2).c_str(),
                  normal.format(2).c_str(), radius.format(2).c_str(), invalid);
      std::fflush(stdout);
    }
  }
  return 0;
}

}  // namespace
}  // namespace scbt

int main(int argc, char** argv) { return scbt::run(argc, argv); }
