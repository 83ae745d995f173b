#include "scbt_ros/conversions.h"

#include <gtest/gtest.h>
#include <sensor_msgs/image_encodings.h>

#include <boost/make_shared.hpp>
#include <nlohmann/json.hpp>

#include "scbt_ros/node_options.h"
#include "scbt_ros/state_report.h"

namespace scbt::ros_node {
namespace {

namespace enc = sensor_msgs::image_encodings;

sensor_msgs::ImagePtr image_msg(const cv::Mat& m, const std::string& encoding) {
  auto msg = boost::make_shared<sensor_msgs::Image>();
  msg->height = m.rows;
  msg->width = m.cols;
  msg->encoding = encoding;
  msg->step = m.cols * m.elemSize();
  msg->data.assign(m.data, m.data + m.total() * m.elemSize());
  return msg;
}

TEST(Conversions, PolygonRoundTripKeepsVerticesAndHeader) {
  const Polygon p = {{1.5, 2.25}, {100.0, 3.0}, {50.75, 80.5}};
  std_msgs::Header header;
  header.stamp = ros::Time(12, 345);
  header.frame_id = "cam";
  const auto msg = to_polygon_msg(p, header);
  EXPECT_EQ(msg.header.stamp, header.stamp);
  EXPECT_EQ(msg.header.frame_id, "cam");
  EXPECT_EQ(from_polygon_msg(msg.polygon), p);
}

TEST(Conversions, RegionBecomesABox) {
  sensor_msgs::RegionOfInterest roi;
  roi.x_offset = 10;
  roi.y_offset = 20;
  roi.width = 30;
  roi.height = 40;
  EXPECT_EQ(from_roi_msg(roi), cv::Rect(10, 20, 30, 40));
  roi.width = 0;
  EXPECT_THROW(from_roi_msg(roi), std::invalid_argument);
  // uint32 offsets beyond an int are refused by value, not wrapped or saturated.
  roi.width = 30;
  roi.x_offset = 4294967295u;
  try {
    from_roi_msg(roi);
    ADD_FAILURE() << "a box at x 4294967295 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("4294967295) is out of range"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(pixel_box(0, 0, 1e30, 10), std::invalid_argument);
}

TEST(Conversions, RgbIsSwappedToBgrAndMonoIsShared) {
  cv::Mat rgb(2, 3, CV_8UC3, cv::Scalar(10, 20, 30));
  const cv::Mat bgr = to_tracker_image(image_msg(rgb, enc::RGB8));
  ASSERT_EQ(bgr.type(), CV_8UC3);
  EXPECT_EQ(bgr.at<cv::Vec3b>(1, 2), cv::Vec3b(30, 20, 10));
  const auto mono_msg = image_msg(cv::Mat(2, 3, CV_8UC1, cv::Scalar(7)), enc::MONO8);
  const cv::Mat mono = to_tracker_image(mono_msg);
  EXPECT_EQ(mono.type(), CV_8UC1);
  EXPECT_EQ(mono.data, mono_msg->data.data());
}

TEST(Conversions, OtherEncodingsAreRefusedByName) {
  const cv::Mat m(2, 3, CV_16UC1, cv::Scalar(1000));
  try {
    to_tracker_image(image_msg(m, enc::MONO16));
    FAIL() << "mono16 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("mono16"), std::string::npos) << e.what();
  }
  auto truncated = image_msg(cv::Mat(4, 4, CV_8UC3), enc::BGR8);
  truncated->data.resize(10);
  EXPECT_THROW(to_tracker_image(truncated), std::invalid_argument);
}

TEST(Conversions, DepthIsTakenAsItIsInEitherEncoding) {
  // The result shares the message's pixels: the message must outlive it.
  const auto mm = image_msg(cv::Mat(2, 2, CV_16UC1, cv::Scalar(1500)), enc::TYPE_16UC1);
  const cv::Mat shared = to_depth_image(mm);
  ASSERT_EQ(shared.type(), CV_16UC1);
  EXPECT_EQ(shared.at<std::uint16_t>(1, 1), 1500);
  EXPECT_EQ(shared.data, mm->data.data());
  const auto metres = image_msg(cv::Mat(2, 2, CV_32FC1, cv::Scalar(0.75)), enc::TYPE_32FC1);
  EXPECT_FLOAT_EQ(to_depth_image(metres).at<float>(0, 1), 0.75f);
  try {
    to_depth_image(image_msg(cv::Mat(2, 2, CV_8UC1), enc::MONO8));
    FAIL() << "mono8 depth accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("mono8"), std::string::npos) << e.what();
  }
}

TEST(Conversions, CameraInfoGivesIntrinsicsAndDistortion) {
  sensor_msgs::CameraInfo info;
  info.K = {500, 0, 320, 0, 510, 240, 0, 0, 1};
  info.distortion_model = "plumb_bob";
  info.D = {0.1, -0.05, 0.001, 0.002, 0.0};
  const PinholeIntrinsics camera = from_camera_info_msg(info);
  EXPECT_EQ(camera.fx, 500);
  EXPECT_EQ(camera.fy, 510);
  EXPECT_EQ(camera.cx, 320);
  EXPECT_EQ(camera.cy, 240);
  EXPECT_EQ(camera.distortion, info.D);
  info.distortion_model = "equidistant";
  EXPECT_THROW(from_camera_info_msg(info), std::invalid_argument);
  info.D.assign(5, 0.0);  // no distortion: the model's name does not matter
  EXPECT_TRUE(from_camera_info_msg(info).distortion.empty());
  info.K = {};
  EXPECT_THROW(from_camera_info_msg(info), std::invalid_argument);
}

TEST(StateReport, TrackedFrameCarriesStateConfidenceHeldTimingsAndDrops) {
  TrackResult result;
  result.held = true;
  result.state = TrackState::kLost;
  result.confidence = 0.125;
  result.stages.search_ms = 0.375;
  result.line_ms = 0.25;
  result.grouping_ms = 0.5;
  FrameReport report{FrameEvent::kTracked};
  report.frame = 7;
  report.dropped_total = 3;
  report.dropped_since_last = 1;
  report.result = &result;
  const auto json = nlohmann::json::parse(state_json(report));
  EXPECT_EQ(json["event"], "tracked");
  EXPECT_EQ(json["frame"], 7);
  EXPECT_EQ(json["held"], true);
  EXPECT_EQ(json["dropped_frames"], 3);
  EXPECT_EQ(json["dropped_since_last"], 1);
  EXPECT_DOUBLE_EQ(json["timings_ms"]["total"].get<double>(), 0.75);
  EXPECT_DOUBLE_EQ(json["timings_ms"]["search"].get<double>(), 0.375);
  EXPECT_EQ(json["state"], "lost");
  EXPECT_DOUBLE_EQ(json["confidence"].get<double>(), 0.125);
  EXPECT_FALSE(nlohmann::json::parse(state_json(FrameReport{})).contains("held"));
  EXPECT_FALSE(nlohmann::json::parse(state_json(FrameReport{})).contains("state"));
  const auto initialised = nlohmann::json::parse(state_json(FrameReport{FrameEvent::kInitialised}));
  EXPECT_EQ(initialised["state"], "tracking");
  EXPECT_TRUE(initialised["confidence"].is_null());
  EXPECT_FALSE(initialised.contains("reason"));
}

TEST(StateReport, FailedFrameSaysWhy) {
  FrameReport report{FrameEvent::kFailed};
  report.reason = "frame size changed from 640x480 to 320x240";
  const auto json = nlohmann::json::parse(state_json(report));
  EXPECT_EQ(json["event"], "failed");
  EXPECT_EQ(json["reason"], "frame size changed from 640x480 to 320x240");
  EXPECT_FALSE(json.contains("state"));
}

}  // namespace
}  // namespace scbt::ros_node
