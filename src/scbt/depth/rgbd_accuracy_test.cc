// Accuracy of the lift to 3-D on rendered RGB-D scenes: the true outline of a bowl's rim and of
// a box's top, at 0.4-1.5 m, with a noisy depth sensor that loses 20 % of the outline's depth.
// Prints the worst errors per distance and asserts both the targets (centroid 3 mm up to 0.6 m and
// 1 % of the distance beyond, normal 2 degrees, radius 2 %) and, much tighter, the errors measured
// on this code with a margin (kMeasured below), so that a worse lift fails long before it misses
// a target.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "scbt/depth/boundary_3d.h"
#include "scbt/synthetic/rgbd_scene.h"
#include "scbt/synthetic/rgbd_sensor.h"

namespace scbt {
namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;

struct WorstErrors {
  double centroid = 0.0;  // metres
  double normal = 0.0;    // degrees
  double radius = 0.0;    // share of the true radius
  int invalid = 0;
};

// Centroid target: 3 mm up to 0.6 m, 1 % of the distance beyond.
double centroid_bound(double distance) { return distance <= 0.6 ? 0.003 : 0.01 * distance; }

// The worst errors measured over both seeds: centroid (mm), normal (degrees), radius (%).
struct Measured {
  RimShape shape;
  double distance;
  double centroid_mm, normal_deg, radius_pct;
};
constexpr Measured kMeasured[] = {
    {RimShape::kBowl, 0.4, 0.07, 0.00, 0.05}, {RimShape::kBowl, 0.6, 0.13, 0.00, 0.05},
    {RimShape::kBowl, 1.0, 0.39, 0.02, 0.06}, {RimShape::kBowl, 1.5, 2.24, 0.00, 0.15},
    {RimShape::kBox, 0.4, 0.09, 0.03, 0.0},   {RimShape::kBox, 0.6, 0.27, 0.12, 0.0},
    {RimShape::kBox, 1.0, 0.50, 0.26, 0.0},   {RimShape::kBox, 1.5, 0.85, 0.70, 0.0},
};

// The bound near a measured error: half as much again plus a slack for a figure at 0 (0.1 mm,
// 0.05 degrees, 0.05 %). The scenes and the sensor's noise are seeded, so a run repeats the
// figures to the last digit on one machine; the margin is for other compilers and CPUs and
// for a harmless change of the outline's sampling, and stays 3-70x under the targets.
double near(double measured, double slack) { return 1.5 * measured + slack; }

WorstErrors measure(RimShape shape, double distance, std::uint32_t seed) {
  RgbdSceneOptions scene;
  scene.shape = shape;
  scene.seed = seed;
  DepthSensorOptions sensor;
  sensor.seed = seed;
  sensor.outline_missing_share = 0.2;
  RimPathOptions path;
  path.start = {-0.05, 0.02, distance};
  path.end = {0.05, -0.02, distance + 0.03};
  WorstErrors worst;
  const std::vector<RimPose> poses = rim_path(path, 6);
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const RgbdFrame frame = render_rgbd_frame(scene, poses[i], static_cast<int>(i));
    const cv::Mat depth = apply_depth_sensor(frame.clean_depth, frame.truth, sensor, i);
    const Boundary3d rim = lift_boundary_to_3d(frame.truth, depth, scene.camera);
    if (!rim.valid) {
      ++worst.invalid;
      continue;
    }
    worst.centroid = std::max(worst.centroid, (rim.centroid - frame.centre).norm());
    worst.normal = std::max(
        worst.normal, std::acos(std::clamp(rim.normal.dot(frame.normal), -1.0, 1.0)) / kDegree);
    if (shape == RimShape::kBowl)
      worst.radius = std::max(
          worst.radius, rim.circle.found ? std::abs(rim.circle.radius / frame.radius - 1.0) : 1.0);
    else
      EXPECT_FALSE(rim.circle.found) << "a box's top is not a circle";
  }
  return worst;
}

class RgbdAccuracy : public testing::TestWithParam<std::tuple<RimShape, double>> {};

TEST_P(RgbdAccuracy, TrueOutlineWithTwentyPercentOfItsDepthMissing) {
  const auto [shape, distance] = GetParam();
  const Measured* measured = nullptr;
  for (const Measured& m : kMeasured) {
    if (m.shape == shape && m.distance == distance) measured = &m;
  }
  ASSERT_NE(measured, nullptr);
  for (std::uint32_t seed : {1u, 2u}) {
    const WorstErrors worst = measure(shape, distance, seed);
    std::printf(
        "%s at %.1f m (seed %u): worst centroid error %.2f mm (%.2f %%), normal %.2f deg, "
        "radius %.2f %%, invalid frames %d\n",
        shape == RimShape::kBowl ? "bowl" : "box", distance, seed, worst.centroid * 1000.0,
        100.0 * worst.centroid / distance, worst.normal, 100.0 * worst.radius, worst.invalid);
    EXPECT_EQ(worst.invalid, 0);
    EXPECT_LE(worst.centroid, centroid_bound(distance));
    EXPECT_LE(worst.normal, 2.0);
    EXPECT_LE(worst.centroid * 1000.0, near(measured->centroid_mm, 0.1));
    EXPECT_LE(worst.normal, near(measured->normal_deg, 0.05));
    if (shape == RimShape::kBowl) {
      EXPECT_LE(worst.radius, 0.02);
      EXPECT_LE(worst.radius * 100.0, near(measured->radius_pct, 0.05));
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Distances, RgbdAccuracy,
                         testing::Combine(testing::Values(RimShape::kBowl, RimShape::kBox),
                                          testing::Values(0.4, 0.6, 1.0, 1.5)));

}  // namespace
}  // namespace scbt
