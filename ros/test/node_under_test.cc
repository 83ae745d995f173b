#include "node_under_test.h"

#include <diagnostic_msgs/DiagnosticArray.h>
#include <sensor_msgs/RegionOfInterest.h>
#include <std_msgs/Float32.h>
#include <std_msgs/String.h>

#include <boost/make_shared.hpp>

#include "scbt_ros/conversions.h"

namespace scbt::ros_test {

std::string g_node_path;
std::string g_log_folder;

using std::chrono::milliseconds;

std::vector<SceneFrame> render_test_clip(SceneShape shape, std::uint32_t seed, int frames,
                                         int period) {
  SceneOptions scene;
  scene.shape = shape;
  scene.seed = seed;
  MotionOptions motion;
  motion.period = period;
  return render_clip(scene, smooth_motion_path(motion, frames));
}

sensor_msgs::ImagePtr to_image_msg(const cv::Mat& image, const std::string& encoding,
                                   const ros::Time& stamp, std::uint32_t seq) {
  auto msg = boost::make_shared<sensor_msgs::Image>();
  msg->header.stamp = stamp;
  msg->header.seq = seq;
  msg->header.frame_id = "scbt_test_camera";
  msg->height = image.rows;
  msg->width = image.cols;
  msg->encoding = encoding;
  msg->step = image.cols * image.elemSize();
  msg->data.assign(image.data, image.data + image.total() * image.elemSize());
  return msg;
}

cv::Rect loose_box(const Polygon& outline) {
  const cv::Rect2d tight = bounding_box(outline);
  const double margin = 0.15 * std::max(tight.width, tight.height);
  return cv::Rect(cvRound(tight.x - margin), cvRound(tight.y - margin),
                  cvRound(tight.width + 2 * margin), cvRound(tight.height + 2 * margin));
}

std::vector<double> flatten(const Polygon& polygon) {
  std::vector<double> out;
  for (const Point& p : polygon) {
    out.push_back(p.x);
    out.push_back(p.y);
  }
  return out;
}

ros::Time stamp_of(int k) { return ros::Time(1000.0 + k / 30.0); }

NodeUnderTest::NodeUnderTest(const std::string& name, const std::vector<std::string>& extra_args)
    : name_(name) {
  ros::NodeHandle nh;
  image_ = nh.advertise<sensor_msgs::Image>("/" + name + "/image", 200);
  init_ = nh.advertise<geometry_msgs::PolygonStamped>("/" + name + "/init", 1);
  init_box_ = nh.advertise<sensor_msgs::RegionOfInterest>("/" + name + "/init_box", 1);
  boundary_ = nh.subscribe<geometry_msgs::PolygonStamped>(
      "/" + name + "/boundary", 200,
      [this](const geometry_msgs::PolygonStampedConstPtr& m) { boundaries.push(*m); });
  state_ = nh.subscribe<std_msgs::String>(
      "/" + name + "/state", 200,
      [this](const std_msgs::StringConstPtr& m) { states.push(nlohmann::json::parse(m->data)); });
  confidence_ = nh.subscribe<std_msgs::Float32>(
      "/" + name + "/confidence", 200,
      [this](const std_msgs::Float32ConstPtr& m) { confidences.push(m->data); });
  diagnostics_ = nh.subscribe<diagnostic_msgs::DiagnosticArray>(
      "/diagnostics", 200, [this, name](const diagnostic_msgs::DiagnosticArrayConstPtr& m) {
        for (const auto& status : m->status) {
          if (status.name.rfind("/" + name + ":", 0) == 0) diagnostics.push(status);
        }
      });
  std::vector<std::string> argv = {g_node_path, "__name:=" + name, "image:=/" + name + "/image"};
  argv.insert(argv.end(), extra_args.begin(), extra_args.end());
  process = ChildProcess(argv, g_log_folder + "/" + name + ".log");
}

::testing::AssertionResult NodeUnderTest::connected() {
  const bool ok = wait_until(
      [this] {
        return image_.getNumSubscribers() > 0 && boundary_.getNumPublishers() > 0 &&
               state_.getNumPublishers() > 0 && confidence_.getNumPublishers() > 0 &&
               diagnostics_.getNumPublishers() > 0;
      },
      milliseconds(20000));
  if (ok) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << name_ << " did not connect; its log:\n" << process.log();
}

void NodeUnderTest::publish(const cv::Mat& image, const ros::Time& stamp,
                            const std::string& encoding) {
  image_.publish(to_image_msg(image, encoding, stamp, next_seq_++));
}

void NodeUnderTest::publish_init(const Polygon& polygon) {
  std_msgs::Header header;
  header.stamp = ros::Time::now();
  init_.publish(ros_node::to_polygon_msg(polygon, header));
}

void NodeUnderTest::publish_init_box(const cv::Rect& box) {
  sensor_msgs::RegionOfInterest roi;
  roi.x_offset = box.x;
  roi.y_offset = box.y;
  roi.width = box.width;
  roi.height = box.height;
  init_box_.publish(roi);
}

}  // namespace scbt::ros_test
