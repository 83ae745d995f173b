#include "scbt/depth/boundary_3d.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace scbt {
namespace {

// A flat tilted disk (radius `radius`, centre `centre`, unit `normal`) in front of a wall at
// 2 m, rendered exactly (no noise) into a 16-bit millimetre depth image.
struct DiskScene {
  PinholeIntrinsics camera;
  Eigen::Vector3d centre{0.03, -0.02, 0.8};
  Eigen::Vector3d normal = Eigen::Vector3d(0.0, -0.6, -0.8).normalized();
  double radius = 0.1;

  Eigen::Vector3d rim_point(double angle) const {
    const Eigen::Vector3d u = normal.cross(Eigen::Vector3d::UnitX()).normalized();
    const Eigen::Vector3d v = normal.cross(u);
    return centre + radius * (std::cos(angle) * u + std::sin(angle) * v);
  }

  Polygon boundary(int vertices) const {
    Polygon polygon;
    for (int i = 0; i < vertices; ++i)
      polygon.push_back(project_point(camera, rim_point(2.0 * M_PI * i / vertices)));
    return polygon;
  }

  cv::Mat depth() const {
    cv::Mat image(480, 640, CV_16UC1);
    for (int y = 0; y < image.rows; ++y)
      for (int x = 0; x < image.cols; ++x) {
        const Eigen::Vector3d ray = pixel_ray(camera, Point(x, y));
        const double z = normal.dot(centre) / normal.dot(ray);
        const bool on_disk = (z * ray - centre).norm() <= radius;
        image.at<std::uint16_t>(y, x) =
            static_cast<std::uint16_t>(std::lround((on_disk ? z : 2.0) * 1000));
      }
    return image;
  }
};

TEST(Boundary3d, RecoversATiltedDisk) {
  const DiskScene scene;
  const cv::Mat depth = scene.depth();
  const Boundary3d rim = lift_boundary_to_3d(scene.boundary(72), depth, scene.camera);
  ASSERT_TRUE(rim.valid);
  EXPECT_GE(rim.n_valid, rim.n_samples * 9 / 10);
  EXPECT_LT((rim.centroid - scene.centre).norm(), 0.002);
  EXPECT_GT(rim.normal.dot(scene.normal), std::cos(1.0 * M_PI / 180.0));
  EXPECT_LT(rim.rms, 0.001);
  ASSERT_TRUE(rim.circle.found);
  EXPECT_NEAR(rim.circle.radius, scene.radius, 0.002);
  EXPECT_LT((rim.circle.centre - scene.centre).norm(), 0.002);
}

TEST(Boundary3d, ARectangleIsNotACircle) {
  const DiskScene scene;
  const Polygon square = {{250, 180}, {390, 180}, {390, 300}, {250, 300}};
  const cv::Mat depth(480, 640, CV_16UC1, cv::Scalar(900));
  const Boundary3d rim = lift_boundary_to_3d(square, depth, scene.camera);
  ASSERT_TRUE(rim.valid);
  EXPECT_FALSE(rim.circle.found);
  EXPECT_LT(rim.normal.dot(Eigen::Vector3d(0, 0, -1)) - 1.0, 1e-9);
  EXPECT_NEAR(rim.centroid.z(), 0.9, 1e-9);
  EXPECT_NEAR(rim.centroid.x(), (320 - 319.5) * 0.9 / 525, 1e-9);
}

// A boundary grown 1000 times about the image centre lies far outside the depth image: its
// samples are its vertices, not one every 3 px of its 1.4 million px (which took memory in
// proportion).
TEST(Boundary3d, ABoundaryFarOutsideTheImageTakesNoMoreSamplesThanItsVertices) {
  const DiskScene scene;
  Polygon grown = scene.boundary(72);
  for (Point& p : grown) p = Point(319.5, 239.5) + (p - Point(319.5, 239.5)) * 1000.0;
  const Boundary3d rim = lift_boundary_to_3d(grown, scene.depth(), scene.camera);
  EXPECT_EQ(rim.n_samples, 72);
  EXPECT_FALSE(rim.valid);
}

// A rim partly outside the image: the samples along its edges stop at the image, its vertices
// outside still close the curve, so the centroid is the whole rim's.
TEST(Boundary3d, ARimPartlyOutsideTheImageKeepsItsCentroid) {
  DiskScene scene;
  scene.centre = Eigen::Vector3d(0.45, -0.02, 0.8);  // its right part beyond the image's edge
  const Polygon rim_outline = scene.boundary(72);
  const cv::Mat depth = scene.depth();
  int outside = 0;
  for (const Point& p : rim_outline) outside += p.x > depth.cols;
  ASSERT_GT(outside, 10);
  const Boundary3d rim = lift_boundary_to_3d(rim_outline, depth, scene.camera);
  ASSERT_TRUE(rim.valid);
  int beyond = 0;
  for (const Point& s : rim.samples) beyond += s.x > depth.cols + 10.0;
  EXPECT_LE(beyond, outside);  // vertices only
  EXPECT_LT((rim.centroid - scene.centre).norm(), 0.003);
}

TEST(Boundary3d, InvalidWithoutDepthAndErrorsForBadInput) {
  const DiskScene scene;
  const cv::Mat holes(480, 640, CV_16UC1, cv::Scalar(0));
  const Boundary3d rim = lift_boundary_to_3d(scene.boundary(72), holes, scene.camera);
  EXPECT_FALSE(rim.valid);
  EXPECT_EQ(rim.n_valid, 0);
  EXPECT_GT(rim.n_samples, 72);
  EXPECT_FALSE(lift_boundary_to_3d({{1, 1}, {2, 2}}, scene.depth(), scene.camera).valid);
  EXPECT_THROW(lift_boundary_to_3d(scene.boundary(8), cv::Mat(), scene.camera),
               std::invalid_argument);
  EXPECT_THROW(lift_boundary_to_3d(scene.boundary(8), cv::Mat(4, 4, CV_8UC1), scene.camera),
               std::invalid_argument);
  DepthOptions bad;
  bad.sample_step = 0.0;
  EXPECT_THROW(lift_boundary_to_3d(scene.boundary(8), holes, scene.camera, bad),
               std::invalid_argument);
}

}  // namespace
}  // namespace scbt
