#include "scbt/synthetic/rgbd_scene.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace scbt
