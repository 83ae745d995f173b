#include "scbt/depth/outline_circle.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

namespace scbt {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Rays (z = 1) through `count` points of a 3-D circle.
std::vector<Eigen::Vector3d> circle_rays(const Eigen::Vector3d& centre,
                                         const Eigen::Vector3d& normal, double radius, int count) {
  const Eigen::Vector3d u = normal.unitOrthogonal(), v = normal.cross(u);
  std::vector<Eigen::Vector3d> rays;
  for (int i = 0; i < count; ++i) {
    const double t = 2.0 * kPi * i / count;
    const Eigen::Vector3d p = centre + radius * (std::cos(t) * u + std::sin(t) * v);
    rays.push_back(p / p.z());
  }
  return rays;
}

double best_angle_degrees(const OutlineNormals& outline, const Eigen::Vector3d& truth) {
  const double c = std::max(outline.normals[0].dot(truth), outline.normals[1].dot(truth));
  return std::acos(std::min(1.0, c)) * 180.0 / kPi;
}

// Random poses: 0.3-2 m away, off the optical axis, tilted up to 70 degrees.
TEST(OutlineCircle, OneOfTheTwoNormalsIsTheCirclesOnExactOutlines) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> off(-0.3, 0.3), depth(0.3, 2.0), tilt(0.0, 70.0),
      turn(0.0, 2.0 * kPi), radius(0.03, 0.15);
  for (int trial = 0; trial < 200; ++trial) {
    const double z = depth(rng);
    const Eigen::Vector3d centre(off(rng) * z, off(rng) * z, z);
    const double a = tilt(rng) * kPi / 180.0, b = turn(rng);
    Eigen::Vector3d normal(std::sin(a) * std::cos(b), std::sin(a) * std::sin(b), -std::cos(a));
    if (normal.dot(centre) > 0.0) normal = -normal;
    const OutlineNormals outline =
        circle_normals_from_outline(circle_rays(centre, normal, radius(rng), 60));
    ASSERT_TRUE(outline.found) << trial;
    EXPECT_LT(best_angle_degrees(outline, normal), 0.05) << trial;
    for (const Eigen::Vector3d& n : outline.normals) {
      EXPECT_NEAR(n.norm(), 1.0, 1e-9);
      EXPECT_LT(n.dot(centre), 0.0);  // towards the camera
    }
  }
}

// Half a pixel of noise (fx = 525) on a rim 35 px in radius at 1.5 m, tilted 40 degrees.
TEST(OutlineCircle, NoisyOutlineStillGivesTheTiltWithinADegree) {
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 0.5 / 525.0);
  const Eigen::Vector3d centre(0.05, -0.02, 1.5);
  const double a = 40.0 * kPi / 180.0;
  const Eigen::Vector3d normal(0.0, std::sin(a), -std::cos(a));
  std::vector<Eigen::Vector3d> rays = circle_rays(centre, normal, 0.1, 120);
  for (Eigen::Vector3d& r : rays) r += Eigen::Vector3d(noise(rng), noise(rng), 0.0);
  const OutlineNormals outline = circle_normals_from_outline(rays);
  ASSERT_TRUE(outline.found);
  EXPECT_LT(best_angle_degrees(outline, normal), 1.0);
}

TEST(OutlineCircle, TooFewOrCollinearRaysGiveNothing) {
  EXPECT_FALSE(circle_normals_from_outline({{0, 0, 1}, {0.1, 0, 1}, {0, 0.1, 1}}).found);
  std::vector<Eigen::Vector3d> line;
  for (int i = 0; i < 20; ++i) line.emplace_back(0.01 * i, 0.02 * i, 1.0);
  EXPECT_FALSE(circle_normals_from_outline(line).found);
}

}  // namespace
}  // namespace scbt
