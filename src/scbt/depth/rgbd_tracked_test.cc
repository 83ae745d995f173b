// End to end on rendered RGB-D clips: the tracker follows the rim in the colour frames from the
// true first outline, and each tracked boundary is lifted to 3-D with the noisy depth image that
// lost 20 % of the outline's depth. Printed and asserted per distance: the targets (centroid 3 mm
// up to 0.6 m and 1 % of the distance beyond, normal 2 degrees, radius 2 %), no held frame, and
// the tracked outline's 2-D error and the 3-D errors near what is measured on this code
// (kMeasured below, with its margin).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "scbt/depth/boundary_3d.h"
#include "scbt/synthetic/rgbd_scene.h"
#include "scbt/synthetic/rgbd_sensor.h"
#include "scbt/synthetic/scene.h"
#include "scbt/tracker/tracker.h"

namespace scbt {
namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;

// The worst errors measured: tracked outline's mean distance to the truth (px), centroid (mm),
// normal (degrees), radius (%).
struct Measured {
  RimShape shape;
  double distance;
  double outline_px, centroid_mm, normal_deg, radius_pct;
};
constexpr Measured kMeasured[] = {
    {RimShape::kBowl, 0.6, 0.34, 0.21, 0.16, 0.15},
    {RimShape::kBowl, 1.5, 0.45, 5.39, 1.30, 0.72},
    {RimShape::kBox, 0.6, 0.09, 0.42, 0.11, 0.0},
    {RimShape::kBox, 1.5, 0.21, 1.18, 0.64, 0.0},
};

// The bound near a measured error: half as much again plus a slack (0.1 px, 0.1 mm, 0.05
// degrees, 0.05 %). Rendering, sensor noise and tracker are deterministic, so one machine repeats
// the figures exactly; the margin is for other compilers and CPUs. An outline 0.1 px worse on
// average over a frame is a real change of the tracker's fit; the bowl at 1.5 m's normal bound
// is the 2-degree target, which 1.5 x 1.30 + 0.05 would exceed.
double near(double measured, double slack) { return 1.5 * measured + slack; }

class RgbdTracked : public testing::TestWithParam<std::tuple<RimShape, double>> {};

TEST_P(RgbdTracked, TrackedOutlineWithTwentyPercentOfItsDepthMissing) {
  const auto [shape, distance] = GetParam();
  const Measured* measured = nullptr;
  for (const Measured& m : kMeasured) {
    if (m.shape == shape && m.distance == distance) measured = &m;
  }
  ASSERT_NE(measured, nullptr);
  RgbdSceneOptions scene;
  scene.shape = shape;
  DepthSensorOptions sensor;
  sensor.outline_missing_share = 0.2;
  RimPathOptions path;  // about 1.5 px of image motion per frame
  path.start = {-0.03, 0.01, distance};
  path.end = {0.03, -0.01, distance + 0.02};
  path.sway = 0.005;
  const int frames = 24;
  const std::vector<RimPose> poses = rim_path(path, frames);
  Tracker tracker{TrackerOptions{}};
  double worst_centroid = 0.0, worst_normal = 0.0, worst_radius = 0.0, worst_outline = 0.0;
  int invalid = 0, held = 0;
  for (int i = 0; i < frames; ++i) {
    const RgbdFrame frame = render_rgbd_frame(scene, poses[i], i);
    Polygon boundary = frame.truth;
    if (i == 0) {
      tracker.init(frame.colour, frame.truth);
    } else {
      const TrackResult result = tracker.track(frame.colour);
      boundary = result.boundary;
      held += result.held;
    }
    worst_outline = std::max(worst_outline, mean_boundary_distance(boundary, frame.truth));
    const cv::Mat depth = apply_depth_sensor(frame.clean_depth, frame.truth, sensor, i);
    const Boundary3d rim = lift_boundary_to_3d(boundary, depth, scene.camera);
    if (!rim.valid) {
      ++invalid;
      continue;
    }
    worst_centroid = std::max(worst_centroid, (rim.centroid - frame.centre).norm());
    worst_normal = std::max(
        worst_normal, std::acos(std::clamp(rim.normal.dot(frame.normal), -1.0, 1.0)) / kDegree);
    if (shape == RimShape::kBowl)
      worst_radius = std::max(
          worst_radius, rim.circle.found ? std::abs(rim.circle.radius / frame.radius - 1.0) : 1.0);
  }
  std::printf(
      "tracked %s at %.1f m: worst outline error %.2f px, held %d; worst centroid error "
      "%.2f mm (%.2f %%), normal %.2f deg, radius %.2f %%, invalid frames %d\n",
      shape == RimShape::kBowl ? "bowl" : "box", distance, worst_outline, held,
      worst_centroid * 1000.0, 100.0 * worst_centroid / distance, worst_normal,
      100.0 * worst_radius, invalid);
  EXPECT_EQ(invalid, 0);
  EXPECT_EQ(held, 0);
  EXPECT_LE(worst_outline, near(measured->outline_px, 0.1));
  EXPECT_LE(worst_centroid, distance <= 0.6 ? 0.003 : 0.01 * distance);
  EXPECT_LE(worst_centroid * 1000.0, near(measured->centroid_mm, 0.1));
  // The targets in every case: the far bowl's normal comes from its outline's ellipse
  // (outline_circle.h), which depth noise at 1.5 m (3.6 mm) does not reach.
  EXPECT_LE(worst_normal, 2.0);
  EXPECT_LE(worst_normal, near(measured->normal_deg, 0.05));
  if (shape == RimShape::kBowl) {
    EXPECT_LE(worst_radius, 0.02);
    EXPECT_LE(worst_radius * 100.0, near(measured->radius_pct, 0.05));
  }
}

INSTANTIATE_TEST_SUITE_P(Distances, RgbdTracked,
                         testing::Combine(testing::Values(RimShape::kBowl, RimShape::kBox),
                                          testing::Values(0.6, 1.5)));

}  // namespace
}  // namespace scbt
