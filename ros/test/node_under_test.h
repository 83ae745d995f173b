// The test's side of one scbt_node child process: it starts the node and holds the publishers of
// its inputs and the inboxes of its outputs. Also the rendered clips the tests play.
#pragma once

#include <diagnostic_msgs/DiagnosticStatus.h>
#include <geometry_msgs/PolygonStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/image_encodings.h>

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ros_harness.h"
#include "scbt/synthetic/scene.h"

namespace scbt::ros_test {

// Set by the test's main(): the node binary and the folder for the master's and nodes' logs.
extern std::string g_node_path;
extern std::string g_log_folder;

// A clip of `frames` rendered frames, the object swinging through a cycle every `period` frames
// (60: brisk, up to about 12 px per frame).
std::vector<SceneFrame> render_test_clip(SceneShape shape, std::uint32_t seed, int frames,
                                         int period = 60);

// The image as a message of `encoding` (its bytes as they are), frame_id "scbt_test_camera".
sensor_msgs::ImagePtr to_image_msg(const cv::Mat& image, const std::string& encoding,
                                   const ros::Time& stamp, std::uint32_t seq);

// A box 15 % of the object's size larger than its outline on every side, as a user would draw it.
cv::Rect loose_box(const Polygon& outline);

// [x1, y1, x2, y2, ...] as the ~init_polygon parameter takes it.
std::vector<double> flatten(const Polygon& polygon);

// The stamp the tests give frame `k`: 30 frames per second from t = 1000 s.
ros::Time stamp_of(int k);

// One scbt_node child named `name` reading images on /<name>/image, with `extra_args` (remaps,
// _param:=value) after its name.
class NodeUnderTest {
 public:
  explicit NodeUnderTest(const std::string& name, const std::vector<std::string>& extra_args = {});

  // Waits until the node reads our images and we read its outputs.
  ::testing::AssertionResult connected();

  // Publishes `image` with header.seq counting up from 0 (as a camera driver's would).
  void publish(const cv::Mat& image, const ros::Time& stamp,
               const std::string& encoding = sensor_msgs::image_encodings::BGR8);
  void publish_init(const Polygon& polygon);
  void publish_init_box(const cv::Rect& box);

  const std::string& name() const { return name_; }

  ChildProcess process;
  Inbox<geometry_msgs::PolygonStamped> boundaries;
  Inbox<nlohmann::json> states;
  Inbox<float> confidences;                              // ~confidence
  Inbox<diagnostic_msgs::DiagnosticStatus> diagnostics;  // this node's, from /diagnostics

 private:
  std::string name_;
  ros::Publisher image_;
  ros::Publisher init_;
  ros::Publisher init_box_;
  ros::Subscriber boundary_;
  ros::Subscriber state_;
  ros::Subscriber confidence_;
  ros::Subscriber diagnostics_;
  std::uint32_t next_seq_ = 0;
};

}  // namespace scbt::ros_test
