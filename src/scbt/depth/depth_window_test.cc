#include "scbt/depth/depth_window.h"

#include <gtest/gtest.h>

#include <cstdint>

namespace scbt {
namespace {

// A vertical edge at x = 20: the object (x >= 20) at `object_mm`, the background behind.
cv::Mat edge_image(std::uint16_t object_mm, std::uint16_t background_mm) {
  cv::Mat depth(40, 40, CV_16UC1, cv::Scalar(background_mm));
  depth.colRange(20, 40).setTo(cv::Scalar(object_mm));
  return depth;
}

const BoundarySample kSample{{19.6, 20.0}, {1.0, 0.0}, false};

TEST(DepthWindow, ReadsTheObjectPastMixedEdgePixels) {
  cv::Mat depth = edge_image(800, 1400);
  depth.col(20).setTo(cv::Scalar(1100));  // mixed pixels on the edge
  std::vector<DepthPixel> scratch;
  const SurfaceDepth surface = nearest_surface_depth(depth, kSample, DepthOptions{}, &scratch);
  EXPECT_NEAR(surface.z, 0.800, 1e-9);
  EXPECT_GT(surface.pixel.x, 20.5);  // where it was read: inside the object
  EXPECT_NEAR(surface.pixel.y, 20.0, 1e-9);
}

TEST(DepthWindow, AveragesTheNearestSurfaceRowByRow) {
  // Inwards from the boundary at x = 19.6: x = 21 reads slightly farther (a mixed pixel within
  // the tolerance), x = 22.. the object itself.
  cv::Mat depth = edge_image(800, 1400);
  depth.col(20).setTo(cv::Scalar(1100));
  depth.col(21).setTo(cv::Scalar(801));
  std::vector<DepthPixel> scratch;
  const SurfaceDepth surface = nearest_surface_depth(depth, kSample, DepthOptions{}, &scratch);
  EXPECT_EQ(surface.first_row, 0);  // x = 21: window_offset 1 from 19.6, rounded
  EXPECT_NEAR(surface.rows[0].z, 0.801, 1e-9);
  EXPECT_NEAR(surface.rows[0].pixel.x, 21.0, 1e-9);
  EXPECT_NEAR(surface.z, 0.801, 1e-9);
  for (int row = 1; row < DepthOptions{}.window_length; ++row) {
    EXPECT_NEAR(surface.rows[row].z, 0.800, 1e-9) << row;
    EXPECT_NEAR(surface.rows[row].pixel.x, 21.0 + row, 1e-9) << row;
  }
}

TEST(DepthWindow, IgnoresHolesAndAnIsolatedNearOutlier) {
  cv::Mat depth = edge_image(800, 1400);
  depth.at<std::uint16_t>(20, 21) = 0;
  depth.at<std::uint16_t>(19, 22) = 0;
  depth.at<std::uint16_t>(21, 21) = 300;  // a flying pixel far in front
  std::vector<DepthPixel> scratch;
  EXPECT_NEAR(nearest_surface_depth(depth, kSample, DepthOptions{}, &scratch).z, 0.800, 1e-9);
}

TEST(DepthWindow, TakesTheNearestSurfaceNotTheFartherInside) {
  // A thin rim (two columns) at 0.8 m, a bowl's inside at 0.9 m beyond it.
  cv::Mat depth = edge_image(900, 1400);
  depth.colRange(20, 22).setTo(cv::Scalar(800));
  std::vector<DepthPixel> scratch;
  EXPECT_NEAR(nearest_surface_depth(depth, kSample, DepthOptions{}, &scratch).z, 0.800, 1e-9);
}

TEST(DepthWindow, MissingDepthAndFloatImages) {
  std::vector<DepthPixel> scratch;
  const cv::Mat holes(40, 40, CV_16UC1, cv::Scalar(0));
  EXPECT_EQ(nearest_surface_depth(holes, kSample, DepthOptions{}, &scratch).z, 0.0);
  cv::Mat metres(40, 40, CV_32FC1, cv::Scalar(1.4f));
  metres.colRange(20, 40).setTo(cv::Scalar(0.75f));
  metres.at<float>(20, 21) = std::numeric_limits<float>::quiet_NaN();
  EXPECT_NEAR(nearest_surface_depth(metres, kSample, DepthOptions{}, &scratch).z, 0.75, 1e-6);
}

TEST(DepthWindow, ToleranceGrowsWithDepthSquared) {
  const DepthOptions options;
  EXPECT_DOUBLE_EQ(surface_tolerance(options, 0.3), options.tolerance_floor);
  EXPECT_NEAR(surface_tolerance(options, 2.0), options.outlier_sigmas * options.noise_at_1m * 4.0,
              1e-12);
}

}  // namespace
}  // namespace scbt
