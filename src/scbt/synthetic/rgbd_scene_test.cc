#include "scbt/synthetic/rgbd_scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "scbt/synthetic/rgbd_sensor.h"

namespace scbt {
namespace {

TEST(RgbdScene, TruthMatchesTheRenderedDepth) {
  for (RimShape shape : {RimShape::kBowl, RimShape::kBox}) {
    RgbdSceneOptions options;
    options.shape = shape;
    for (const RimPose& pose : rim_path({}, 3)) {
      const RgbdFrame frame = render_rgbd_frame(options, pose);
      ASSERT_EQ(frame.truth.size(), frame.truth_rim.size());
      EXPECT_LT(frame.normal.dot(frame.centre), 0.0);  // faces the camera
      // Just inside each true outline vertex (towards the projected centre) the depth is the
      // rim's; just outside it is farther (the table or the object's side).
      const Point centre = project_point(options.camera, frame.centre);
      for (std::size_t i = 0; i < frame.truth.size(); ++i) {
        const Point towards = centre - frame.truth[i];
        const Point inward = towards / std::hypot(towards.x, towards.y);
        const Point inside = frame.truth[i] + inward * 1.5, outside = frame.truth[i] - inward * 2.5;
        const float z_in = frame.clean_depth.at<float>(cvRound(inside.y), cvRound(inside.x));
        const float z_out = frame.clean_depth.at<float>(cvRound(outside.y), cvRound(outside.x));
        EXPECT_NEAR(z_in, frame.truth_rim[i].z(), 0.006) << i;
        EXPECT_GT(z_out, frame.truth_rim[i].z() - 0.002) << i;
      }
    }
  }
}

TEST(RgbdScene, SameSeedSameFramesAndABowlIsLowerInside) {
  const RgbdSceneOptions options;
  const RimPose pose;
  const RgbdFrame a = render_rgbd_frame(options, pose, 4), b = render_rgbd_frame(options, pose, 4);
  EXPECT_EQ(cv::norm(a.colour, b.colour, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(a.depth, b.depth, cv::NORM_INF), 0.0);
  const Point centre = project_point(options.camera, a.centre);
  EXPECT_GT(a.clean_depth.at<float>(cvRound(centre.y), cvRound(centre.x)), a.centre.z() + 0.02);
}

TEST(RgbdSensor, NoiseGrowsWithDepthSquaredAndTheOutlineLosesItsShare) {
  DepthSensorOptions options;
  options.hole_blobs = 0;
  options.outline_missing_share = 0.0;
  for (double z : {1.0, 2.0}) {
    const cv::Mat clean(200, 200, CV_32FC1, cv::Scalar(z));
    cv::Mat measured;
    apply_depth_sensor(clean, {}, options).convertTo(measured, CV_64F, options.depth_scale);
    cv::Scalar mean, stddev;
    cv::meanStdDev(measured, mean, stddev);
    EXPECT_NEAR(stddev[0], options.noise_at_1m * z * z, 0.15 * options.noise_at_1m * z * z);
    EXPECT_NEAR(mean[0], z, 0.001);
  }
  options.outline_missing_share = 0.2;
  const cv::Mat clean(200, 200, CV_32FC1, cv::Scalar(1.0));
  const Polygon square = {{50, 50}, {150, 50}, {150, 150}, {50, 150}};
  const cv::Mat depth = apply_depth_sensor(clean, square, options, 3);
  int missing = 0, total = 0;
  for (int x = 50; x < 150; ++x)
    for (int y : {50, 150})
      total += 2,
          missing += (depth.at<std::uint16_t>(y, x) == 0) + (depth.at<std::uint16_t>(x, y) == 0);
  EXPECT_NEAR(static_cast<double>(missing) / total, 0.2, 0.05);
}

TEST(RgbdSensor, EdgeArtefactsSmearTwoPixelsEachSideAndHolesTakeTheirShare) {
  // A vertical step: 0.6 m left of column 100, 0.9 m from it on.
  cv::Mat clean(200, 200, CV_32FC1, cv::Scalar(0.6));
  clean.colRange(100, 200).setTo(0.9);
  DepthSensorOptions options = edge_artefact_sensor(5);
  options.noise_at_1m = 0.0;
  options.hole_blobs = 0;
  options.hole_share = 0.0;
  options.depth_scale = 0.0001;  // finer than the smallest blend checked
  cv::Mat depth;
  apply_depth_sensor(clean, {}, options).convertTo(depth, CV_64F, options.depth_scale);
  double max_blend[4] = {0, 0, 0, 0};  // columns 98..101 (rings 2, 1 | 1, 2)
  for (int y = 1; y + 1 < depth.rows; ++y) {
    for (int x = 98; x <= 101; ++x) {
      const double own = clean.at<float>(y, x), other = x < 100 ? 0.9 : 0.6;
      max_blend[x - 98] =
          std::max(max_blend[x - 98], (depth.at<double>(y, x) - own) / (other - own));
    }
    EXPECT_NEAR(depth.at<double>(y, 97), 0.6, 1e-4);  // the third ring is clean
    EXPECT_NEAR(depth.at<double>(y, 102), 0.9, 1e-4);
  }
  EXPECT_GT(max_blend[1], 0.4);  // the edge pixels: coverage-weighted, w up to 0.5
  EXPECT_LE(max_blend[1], 0.5 + 1e-3);
  EXPECT_GT(max_blend[2], 0.4);
  EXPECT_LE(max_blend[2], 0.5 + 1e-3);
  EXPECT_GT(max_blend[0], 0.2);  // the ring behind: up to 0.25
  EXPECT_LE(max_blend[0], 0.25 + 1e-3);
  EXPECT_GT(max_blend[3], 0.2);
  EXPECT_LE(max_blend[3], 0.25 + 1e-3);

  options = edge_artefact_sensor(5);
  options.hole_blobs = 0;
  options.outline_missing_share = 0.0;
  const cv::Mat flat(240, 320, CV_32FC1, cv::Scalar(1.0));
  const cv::Mat holes = apply_depth_sensor(flat, {}, options) == 0;
  const double share = cv::countNonZero(holes) / static_cast<double>(holes.total());
  EXPECT_GE(share, 0.10);
  EXPECT_LT(share, 0.13);
}

}  // namespace
}  // namespace scbt
