#include "scbt/depth/circle_fit.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

namespace scbt {
namespace {

TEST(CircleFit, RecoversCentreAndRadiusFromAnArc) {
  std::mt19937 random(11);
  std::normal_distribution<double> noise(0.0, 0.0005);
  const Eigen::Vector3d normal = Eigen::Vector3d(0.2, -0.7, -0.6).normalized();
  const Eigen::Vector3d centre(0.05, 0.02, 0.9);
  const Eigen::Vector3d u = normal.cross(Eigen::Vector3d::UnitX()).normalized();
  const Eigen::Vector3d v = normal.cross(u);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 80; ++i) {  // 240 degrees of arc only
    const double angle = i * (4.0 * M_PI / 3.0) / 80;
    points.push_back(centre + (0.09 + noise(random)) * (std::cos(angle) * u + std::sin(angle) * v));
  }
  const CircleFit circle = fit_circle_in_plane(points, centre + 0.03 * u, normal);
  ASSERT_TRUE(circle.found);
  EXPECT_LT((circle.centre - centre).norm(), 0.0005);
  EXPECT_NEAR(circle.radius, 0.09, 0.0003);
  EXPECT_NEAR(circle.rms, 0.0005, 0.0002);
}

TEST(CircleFit, CollinearPointsFindNothing) {
  const std::vector<Eigen::Vector3d> line = {{0, 0, 1}, {0.1, 0, 1}, {0.2, 0, 1}, {0.3, 0, 1}};
  EXPECT_FALSE(fit_circle_in_plane(line, {0, 0, 1}, {0, 0, -1}).found);
}

}  // namespace
}  // namespace scbt
