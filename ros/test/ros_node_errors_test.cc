// scbt_node's behaviour on bad input: images of a wrong encoding get an error in the log (on
// /rosout) and the node goes on; bad parameters stop it at start with an error naming them; the
// launch file starts a working node.
#include <rosgraph_msgs/Log.h>

#include <cstdlib>

#include "node_under_test.h"
#include "scbt/app/ci_requirement.h"
#include "scbt_ros/conversions.h"

namespace scbt::ros_test {
namespace {

using std::chrono::milliseconds;

TEST(RosNode, WrongEncodingIsLoggedAsAnErrorAndTheNodeGoesOn) {
  Inbox<rosgraph_msgs::Log> log;
  ros::NodeHandle nh;
  ros::Subscriber rosout = nh.subscribe<rosgraph_msgs::Log>(
      "/rosout", 100, [&log](const rosgraph_msgs::LogConstPtr& m) { log.push(*m); });
  const std::vector<SceneFrame> clip = render_test_clip(SceneShape::kBox, 11, 3);
  const cv::Rect box = loose_box(clip[0].truth);
  ros::param::set("/scbt_enc/init_box", std::vector<int>{box.x, box.y, box.width, box.height});
  NodeUnderTest node("scbt_enc");
  ASSERT_TRUE(node.connected());
  ASSERT_TRUE(wait_until([&] { return rosout.getNumPublishers() > 0; }, milliseconds(10000)));

  // 16-bit depth-like pixels on the colour topic.
  cv::Mat depth(480, 640, CV_16UC1, cv::Scalar(1200));
  node.publish(depth, stamp_of(0), sensor_msgs::image_encodings::TYPE_16UC1);
  bool logged = false;
  while (!logged) {
    const auto entry = log.pop(milliseconds(10000));
    ASSERT_TRUE(entry) << "no error logged; node log:\n" << node.process.log();
    logged = entry->name == "/scbt_enc" && entry->level == rosgraph_msgs::Log::ERROR &&
             entry->msg.find("encoding '16UC1'") != std::string::npos;
  }
  EXPECT_FALSE(node.boundaries.pop(milliseconds(200)));  // nothing tracked on it

  // Still alive: the next good frame is initialised from ~init_box and published.
  node.publish(clip[0].image, stamp_of(1));
  const auto boundary = node.boundaries.pop(milliseconds(10000));
  ASSERT_TRUE(boundary) << node.process.log();
  EXPECT_EQ(boundary->header.stamp, stamp_of(1));
  EXPECT_LT(mean_boundary_distance(ros_node::from_polygon_msg(boundary->polygon), clip[0].truth),
            1.5);  // the box's outline found inside ~init_box
  EXPECT_TRUE(node.process.running());
  EXPECT_EQ(node.process.stop(), 0) << node.process.log();
}

// Waits up to 10 s for an ERROR line of `node` on /rosout containing `text`.
::testing::AssertionResult error_logged(Inbox<rosgraph_msgs::Log>* log, const NodeUnderTest& node,
                                        const std::string& text) {
  while (const auto entry = log->pop(milliseconds(10000))) {
    if (entry->name == "/" + node.name() && entry->level == rosgraph_msgs::Log::ERROR &&
        entry->msg.find(text) != std::string::npos) {
      return ::testing::AssertionSuccess();
    }
  }
  return ::testing::AssertionFailure() << "no error containing \"" << text << "\" logged";
}

// Errors are limited per reason, not per line of code: a second, different bad image right after
// the first is logged too, and a frame the tracker rejects says why in ~state.
TEST(RosNode, EachDifferentErrorIsLoggedAndAFailedFrameSaysWhy) {
  Inbox<rosgraph_msgs::Log> log;
  ros::NodeHandle nh;
  ros::Subscriber rosout = nh.subscribe<rosgraph_msgs::Log>(
      "/rosout", 100, [&log](const rosgraph_msgs::LogConstPtr& m) { log.push(*m); });
  const std::vector<SceneFrame> clip = render_test_clip(SceneShape::kBox, 11, 1);
  ros::param::set("/scbt_why/init_polygon", flatten(clip[0].truth));
  NodeUnderTest node("scbt_why");
  ASSERT_TRUE(node.connected());
  ASSERT_TRUE(wait_until([&] { return rosout.getNumPublishers() > 0; }, milliseconds(10000)));

  node.publish(cv::Mat(480, 640, CV_16UC1, cv::Scalar(1200)), stamp_of(0),
               sensor_msgs::image_encodings::TYPE_16UC1);
  EXPECT_TRUE(error_logged(&log, node, "encoding '16UC1'")) << node.process.log();
  node.publish(cv::Mat(480, 640, CV_16UC1, cv::Scalar(1200)), stamp_of(1),
               sensor_msgs::image_encodings::MONO16);
  EXPECT_TRUE(error_logged(&log, node, "encoding 'mono16'")) << node.process.log();

  node.publish(clip[0].image, stamp_of(2));
  auto state = node.states.pop(milliseconds(10000));
  ASSERT_TRUE(state) << node.process.log();
  EXPECT_EQ((*state)["event"], "initialised");
  // Frames of other sizes than the one it was initialised on: failed, each with its reason, each
  // reason logged.
  int stamp = 3;
  for (const cv::Size size : {cv::Size(320, 240), cv::Size(330, 240)}) {
    node.publish(clip[0].image(cv::Rect(cv::Point(0, 0), size)).clone(), stamp_of(stamp++));
    state = node.states.pop(milliseconds(10000));
    ASSERT_TRUE(state) << node.process.log();
    EXPECT_EQ((*state)["event"], "failed");
    const std::string reason = (*state).value("reason", "");
    EXPECT_NE(reason.find("to " + std::to_string(size.width) + "x240"), std::string::npos)
        << reason;
    EXPECT_TRUE(error_logged(&log, node, reason)) << node.process.log();
  }
  EXPECT_EQ(node.process.stop(), 0) << node.process.log();
}

// Starts the node with `args` and expects it to exit with code 2 within 20 s, its log naming
// `expected`.
void expect_refused(const std::string& name, const std::vector<std::string>& args,
                    const std::string& expected) {
  std::vector<std::string> argv = {g_node_path, "__name:=" + name};
  argv.insert(argv.end(), args.begin(), args.end());
  ChildProcess node(argv, g_log_folder + "/" + name + ".log");
  const auto code = node.wait(milliseconds(20000));
  ASSERT_TRUE(code) << name << " did not exit; log:\n" << node.log();
  EXPECT_EQ(*code, 2) << node.log();
  EXPECT_NE(node.log().find(expected), std::string::npos) << node.log();
}

TEST(RosNode, BadParametersStopItWithAnErrorNamingThem) {
  expect_refused("scbt_bad1", {"_filter_distance:=-5"}, "filter_distance");
  expect_refused("scbt_bad2", {"_seed_stride:=two"},
                 "parameter /scbt_bad2/seed_stride: seed_stride must be a whole number, got 'two'");
  expect_refused("scbt_bad6", {"_shape_weight:=101"},
                 "parameter /scbt_bad6/shape_weight: shape_weight must be in [0, 100], got 101");
  expect_refused("scbt_bad3", {"_detector:=hough"}, "hough");
  expect_refused("scbt_bad4", {"_init_box:=[10, 10, 0, 40]"}, "positive width");
  expect_refused("scbt_bad5", {"_init_polygon:=[1, 2, 3]"}, "/scbt_bad5/init_polygon");
}

TEST(RosNode, UnknownParametersAreWarnedAbout) {
  NodeUnderTest node("scbt_typo", {"_filter_distanse:=10", "_min_depth:=0.2", "_max_depth:=4.5"});
  ASSERT_TRUE(node.connected());
  EXPECT_NE(node.process.log().find("unknown parameter /scbt_typo/filter_distanse"),
            std::string::npos)
      << node.process.log();
  // Known ones, though not the tracker's.
  EXPECT_EQ(node.process.log().find("unknown parameter /scbt_typo/min_depth"), std::string::npos)
      << node.process.log();
  EXPECT_EQ(node.process.log().find("unknown parameter /scbt_typo/max_depth"), std::string::npos)
      << node.process.log();
  EXPECT_EQ(node.process.stop(), 0);
}

// roslaunch scbt_ros scbt.launch, found through ROS_PACKAGE_PATH=<build>/ros, on our master.
TEST(RosNode, LaunchFileStartsATrackingNode) {
  SCBT_REQUIRE(on_path("roslaunch"), "roslaunch (python3-roslaunch; scripts/setup.sh installs it)");
  const std::string package_dir = g_node_path.substr(0, g_node_path.rfind('/'));
  setenv("ROS_PACKAGE_PATH", package_dir.c_str(), 1);
  const std::vector<SceneFrame> clip = render_test_clip(SceneShape::kRim, 13, 2);
  const cv::Rect box = loose_box(clip[0].truth);
  ros::NodeHandle nh;
  Inbox<geometry_msgs::PolygonStamped> boundaries;
  ros::Publisher image = nh.advertise<sensor_msgs::Image>("/launched/image", 10);
  ros::Subscriber boundary = nh.subscribe<geometry_msgs::PolygonStamped>(
      "/scbt/boundary", 10,
      [&](const geometry_msgs::PolygonStampedConstPtr& m) { boundaries.push(*m); });
  const std::string init_box = "init_box:=[" + std::to_string(box.x) + "," + std::to_string(box.y) +
                               "," + std::to_string(box.width) + "," + std::to_string(box.height) +
                               "]";
  ChildProcess launch({"roslaunch", "scbt_ros", "scbt.launch", "image:=/launched/image", init_box},
                      g_log_folder + "/roslaunch.log");
  ASSERT_TRUE(
      wait_until([&] { return image.getNumSubscribers() > 0 && boundary.getNumPublishers() > 0; },
                 milliseconds(30000)))
      << launch.log();
  image.publish(to_image_msg(clip[0].image, "bgr8", stamp_of(0), 0));
  const auto first = boundaries.pop(milliseconds(10000));
  ASSERT_TRUE(first) << launch.log();
  // The rim found inside the box, on the frame it initialised on.
  EXPECT_LT(mean_boundary_distance(ros_node::from_polygon_msg(first->polygon), clip[0].truth), 1.5);
  image.publish(to_image_msg(clip[1].image, "bgr8", stamp_of(1), 1));
  const auto second = boundaries.pop(milliseconds(10000));
  ASSERT_TRUE(second) << launch.log();
  EXPECT_EQ(second->header.stamp, stamp_of(1));
  EXPECT_EQ(launch.stop(milliseconds(10000)), 0) << launch.log();
}

}  // namespace
}  // namespace scbt::ros_test
