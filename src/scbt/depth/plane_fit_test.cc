#include "scbt/depth/plane_fit.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

namespace scbt {
namespace {

TEST(PlaneFit, RecoversAPlaneThroughNoiseAndOutliers) {
  std::mt19937 random(3);
  std::normal_distribution<double> noise(0.0, 0.001);
  std::uniform_real_distribution<double> uniform(-0.1, 0.1);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Vector3d normal = Eigen::Vector3d(uniform(random), -1.0, -1.0).normalized();
    const Eigen::Vector3d origin(uniform(random), uniform(random), 0.9);
    const Eigen::Vector3d u = normal.cross(Eigen::Vector3d::UnitX()).normalized();
    const Eigen::Vector3d v = normal.cross(u);
    std::vector<Eigen::Vector3d> points;
    for (int i = 0; i < 150; ++i)
      points.push_back(origin + uniform(random) * u + uniform(random) * v + noise(random) * normal);
    for (int i = 0; i < 30; ++i)  // outliers, 2-12 cm off the plane
      points[i * 5] += (0.02 + std::abs(uniform(random))) * normal;
    points.push_back(Eigen::Vector3d::Constant(std::nan("")));
    const PlaneFit fit = fit_plane_robust(points, DepthOptions{});
    ASSERT_TRUE(fit.found);
    EXPECT_GT(fit.normal.dot(normal), std::cos(0.5 * M_PI / 180.0));  // also: towards the camera
    EXPECT_LT(fit.normal.dot(origin), 0.0);
    EXPECT_NEAR(fit.rms, 0.001, 0.0004);
    EXPECT_LE(fit.n_inliers, 150 - 30 + 2);
    EXPECT_GE(fit.n_inliers, 110);
    for (int i = 0; i < 30; ++i) EXPECT_FALSE(fit.inlier[i * 5]);
  }
}

TEST(PlaneFit, CollinearOrTooFewPointsFindNothing) {
  EXPECT_FALSE(fit_plane_robust({{0, 0, 1}, {0.1, 0, 1}}, DepthOptions{}).found);
  EXPECT_FALSE(
      fit_plane_robust({{0, 0, 1}, {0.1, 0, 1}, {0.2, 0, 1}, {0.3, 0, 1}}, DepthOptions{}).found);
}

TEST(PlaneFit, RayIntersection) {
  PlaneFit plane;
  plane.normal = Eigen::Vector3d(0, 0, -1);
  plane.offset = -2.0;  // z = 2
  Eigen::Vector3d point;
  ASSERT_TRUE(intersect_ray_with_plane(plane, {0.1, -0.2, 1.0}, &point));
  EXPECT_LT((point - Eigen::Vector3d(0.2, -0.4, 2.0)).norm(), 1e-12);
  plane.normal = Eigen::Vector3d(1, 0, 0);
  plane.offset = -1.0;
  EXPECT_FALSE(intersect_ray_with_plane(plane, {0.0, 0.1, 1.0}, &point));  // parallel
  EXPECT_FALSE(intersect_ray_with_plane(plane, {0.5, 0.1, 1.0}, &point));  // behind
}

}  // namespace
}  // namespace scbt
