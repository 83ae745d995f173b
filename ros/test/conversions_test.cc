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

TEST(Conversions, BoxBecomesItsFourCorners) {
  sensor_msgs::RegionOfInterest roi;
  roi.x_offset = 10;
  roi.y_offset = 20;
  roi.width = 30;
  roi.height = 40;
  const Polygon expected = {{10, 20}, {40, 20}, {40, 60}, {10, 60}};
  EXPECT_EQ(from_roi_msg(roi), expected);
  roi.width = 0;
  EXPECT_THROW(from_roi_msg(roi), std::invalid_argument);
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

TEST(Conversions, DepthMillimetresBecomeMetres) {
  const cv::Mat mm(2, 2, CV_16UC1, cv::Scalar(1500));
  const cv::Mat m = to_depth_metres(image_msg(mm, enc::TYPE_16UC1));
  ASSERT_EQ(m.type(), CV_32FC1);
  EXPECT_FLOAT_EQ(m.at<float>(1, 1), 1.5f);
  const cv::Mat f(2, 2, CV_32FC1, cv::Scalar(0.75));
  EXPECT_FLOAT_EQ(to_depth_metres(image_msg(f, enc::TYPE_32FC1)).at<float>(0, 1), 0.75f);
  EXPECT_THROW(to_depth_metres(image_msg(cv::Mat(2, 2, CV_8UC1), enc::MONO8)),
               std::invalid_argument);
}

TEST(StateReport, TrackedFrameCarriesHeldTimingsAndDrops) {
  TrackResult result;
  result.held = true;
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
  EXPECT_FALSE(nlohmann::json::parse(state_json(FrameReport{})).contains("held"));
}

}  // namespace
}  // namespace scbt::ros_node
