#include "scbt/depth/pinhole_camera.h"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

#include "scbt/depth/lens_distortion.h"

namespace scbt {
namespace {

TEST(PinholeCamera, ParsesIntrinsicsAndRejectsBadText) {
  const PinholeIntrinsics camera = parse_intrinsics("525,526.5, 319.5,239.5");
  EXPECT_DOUBLE_EQ(camera.fx, 525.0);
  EXPECT_DOUBLE_EQ(camera.fy, 526.5);
  EXPECT_DOUBLE_EQ(camera.cx, 319.5);
  EXPECT_DOUBLE_EQ(camera.cy, 239.5);
  EXPECT_THROW(parse_intrinsics("525,525,319.5"), std::invalid_argument);
  EXPECT_THROW(parse_intrinsics("525,525,319.5,x"), std::invalid_argument);
  EXPECT_THROW(parse_intrinsics("-1,525,319.5,239.5"), std::invalid_argument);
  EXPECT_THROW(parse_intrinsics("525,525,319.5,239.5,1"), std::invalid_argument);
  PinholeIntrinsics bad;
  bad.distortion = {0.1, 0.2, 0.3};
  EXPECT_THROW(bad.check(), std::invalid_argument);
}

TEST(PinholeCamera, ProjectionInvertsTheRayWithAndWithoutDistortion) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> lateral(-0.5, 0.5), depth(0.4, 3.0);
  for (const std::vector<double>& distortion :
       {std::vector<double>{}, std::vector<double>{0.18, -0.42, 0.001, -0.002, 0.2},
        std::vector<double>{0.1, 0.05, 0.0, 0.001, 0.0, 0.02, 0.01, 0.0}}) {
    PinholeIntrinsics camera;
    camera.distortion = distortion;
    for (int i = 0; i < 200; ++i) {
      const double z = depth(random);
      const Eigen::Vector3d point(lateral(random) * z, lateral(random) * z * 0.75, z);
      const Point pixel = project_point(camera, point);
      const Eigen::Vector3d back = point.z() * pixel_ray(camera, pixel);
      EXPECT_LT((back - point).norm(), 1e-9) << "distortion terms " << distortion.size();
    }
  }
}

TEST(PinholeCamera, UndistortPolygonMatchesAnIdealCamera) {
  PinholeIntrinsics camera;
  camera.distortion = {0.2, -0.3, 0.0, 0.0, 0.0};
  PinholeIntrinsics ideal = camera;
  ideal.distortion.clear();
  const Eigen::Vector3d point(0.2, -0.1, 0.8);
  const Polygon distorted = {project_point(camera, point)};
  const Polygon undistorted = undistort_polygon(camera, distorted);
  const Point expected = project_point(ideal, point);
  EXPECT_NEAR(undistorted[0].x, expected.x, 1e-9);
  EXPECT_NEAR(undistorted[0].y, expected.y, 1e-9);
  EXPECT_GT(std::abs(distorted[0].x - expected.x), 1.0);  // the distortion did move it
}

}  // namespace
}  // namespace scbt
