// scbt_node against a real ROS master: the test starts `rosmaster` on a free loopback port, runs
// the node as a child process, plays rendered clips (src/scbt/synthetic) to it and checks what it
// publishes against the clips' known truth. Exits 77 (ctest: skipped) when rosmaster is missing.
#include <geometry_msgs/PolygonStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Log.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/image_encodings.h>
#include <std_msgs/String.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "ros_harness.h"
#include "scbt/synthetic/scene.h"
#include "scbt/tracker/tracker.h"
#include "scbt_ros/conversions.h"

namespace scbt::ros_test {
namespace {

using std::chrono::milliseconds;

std::string g_node_path;   // --node
std::string g_log_folder;  // the master's and nodes' logs

// A rendered clip: frames and their true outlines.
std::vector<SceneFrame> render_test_clip(SceneShape shape, std::uint32_t seed, int frames) {
  SceneOptions scene;
  scene.shape = shape;
  scene.seed = seed;
  MotionOptions motion;
  motion.period = 60;  // brisk: up to about 12 px per frame
  return render_clip(scene, smooth_motion_path(motion, frames));
}

sensor_msgs::ImagePtr to_image_msg(const cv::Mat& bgr, const std::string& encoding,
                                   const ros::Time& stamp, std::uint32_t seq) {
  auto msg = boost::make_shared<sensor_msgs::Image>();
  msg->header.stamp = stamp;
  msg->header.seq = seq;
  msg->header.frame_id = "scbt_test_camera";
  msg->height = bgr.rows;
  msg->width = bgr.cols;
  msg->encoding = encoding;
  msg->step = bgr.cols * bgr.elemSize();
  msg->data.assign(bgr.data, bgr.data + bgr.total() * bgr.elemSize());
  return msg;
}

std::vector<double> flatten(const Polygon& polygon) {
  std::vector<double> out;
  for (const Point& p : polygon) {
    out.push_back(p.x);
    out.push_back(p.y);
  }
  return out;
}

// One scbt_node child named `name`, reading images on /<name>/image, and the test's ends of its
// topics.
class NodeUnderTest {
 public:
  NodeUnderTest(const std::string& name, const std::vector<std::string>& extra_args = {})
      : name_(name) {
    ros::NodeHandle nh;
    image_ = nh.advertise<sensor_msgs::Image>("/" + name + "/image", 200);
    init_ = nh.advertise<geometry_msgs::PolygonStamped>("/" + name + "/init", 1);
    boundary_ = nh.subscribe<geometry_msgs::PolygonStamped>(
        "/" + name + "/boundary", 200,
        [this](const geometry_msgs::PolygonStampedConstPtr& m) { boundaries.push(*m); });
    state_ = nh.subscribe<std_msgs::String>(
        "/" + name + "/state", 200,
        [this](const std_msgs::StringConstPtr& m) { states.push(nlohmann::json::parse(m->data)); });
    std::vector<std::string> argv = {g_node_path, "__name:=" + name};
    argv.insert(argv.end(), extra_args.begin(), extra_args.end());
    process = ChildProcess(argv, g_log_folder + "/" + name + ".log");
  }

  // Waits until the node reads our images and we read its outputs.
  ::testing::AssertionResult connected() {
    const bool ok = wait_until(
        [this] {
          return image_.getNumSubscribers() > 0 && boundary_.getNumPublishers() > 0 &&
                 state_.getNumPublishers() > 0;
        },
        milliseconds(20000));
    if (ok) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << name_ << " did not connect; its log:\n"
                                         << process.log();
  }

  void publish(const cv::Mat& bgr, const ros::Time& stamp, std::uint32_t seq,
               const std::string& encoding = sensor_msgs::image_encodings::BGR8) {
    image_.publish(to_image_msg(bgr, encoding, stamp, seq));
  }
  void publish_init(const Polygon& polygon) {
    std_msgs::Header header;
    header.stamp = ros::Time::now();
    init_.publish(ros_node::to_polygon_msg(polygon, header));
  }

  ChildProcess process;
  Inbox<geometry_msgs::PolygonStamped> boundaries;
  Inbox<nlohmann::json> states;

 private:
  std::string name_;
  ros::Publisher image_;
  ros::Publisher init_;
  ros::Subscriber boundary_;
  ros::Subscriber state_;
};

ros::Time stamp_of(int frame) { return ros::Time(1000.0 + frame / 30.0); }

// Plays `clip` to `node` one frame at a time, each published after the previous one's boundary
// came back, and checks every boundary: stamped as its image, within 3 px of the truth (mean
// boundary distance) and equal to what the library's Tracker gives on the same frames. clip[0]
// must be the frame the node initialises on. Returns the number of held frames.
int play_and_check(NodeUnderTest* node, const std::vector<SceneFrame>& clip, int first_stamp,
                   const char* what) {
  Tracker reference;
  reference.init(clip[0].image, clip[0].truth);
  int held = 0;
  for (size_t k = 0; k < clip.size(); ++k) {
    SCOPED_TRACE(std::string(what) + " frame " + std::to_string(k));
    const ros::Time stamp = stamp_of(first_stamp + static_cast<int>(k));
    node->publish(clip[k].image, stamp, first_stamp + k);
    const auto boundary = node->boundaries.pop(milliseconds(10000));
    const auto state = node->states.pop(milliseconds(10000));
    if (!boundary || !state) {
      ADD_FAILURE() << "no boundary/state; node log:\n" << node->process.log();
      return held;
    }
    EXPECT_EQ(boundary->header.stamp, stamp);
    EXPECT_EQ(boundary->header.frame_id, "scbt_test_camera");
    const Polygon tracked = ros_node::from_polygon_msg(boundary->polygon);
    EXPECT_LT(mean_boundary_distance(tracked, clip[k].truth, 0.5), 3.0);
    EXPECT_EQ((*state)["event"], k == 0 ? "initialised" : "tracked") << state->dump();
    EXPECT_EQ((*state)["dropped_frames"], 0) << state->dump();
    if (k > 0) {
      const TrackResult expected = reference.track(clip[k].image);
      EXPECT_LT(mean_boundary_distance(tracked, expected.boundary, 0.5), 0.01);
      EXPECT_EQ((*state)["held"], expected.held);
      held += expected.held ? 1 : 0;
    }
  }
  return held;
}

TEST(RosNode, TracksRenderedClipsAndIsReinitialisedByMessage) {
  const std::vector<SceneFrame> rim = render_test_clip(SceneShape::kRim, 3, 40);
  ros::param::set("/scbt_clip/init_polygon", flatten(rim[0].truth));
  NodeUnderTest node("scbt_clip", {"image:=/scbt_clip/image"});
  ASSERT_TRUE(node.connected());
  const int held_rim = play_and_check(&node, rim, 0, "rim");
  EXPECT_LE(held_rim, 2);

  // Another object from another seed: re-initialised through ~init. The init message and the
  // next frame travel on different connections, so the first frame is repeated (new stamps)
  // until the node reports it initialised.
  const std::vector<SceneFrame> box = render_test_clip(SceneShape::kBox, 5, 30);
  node.publish_init(box[0].truth);
  int stamp = 100;
  bool initialised = false;
  for (int attempt = 0; attempt < 50 && !initialised; ++attempt, ++stamp) {
    node.publish(box[0].image, stamp_of(stamp), stamp);
    const auto state = node.states.pop(milliseconds(10000));
    ASSERT_TRUE(state) << node.process.log();
    ASSERT_TRUE(node.boundaries.pop(milliseconds(10000)));
    initialised = (*state)["event"] == "initialised";
  }
  ASSERT_TRUE(initialised) << "~init never applied; node log:\n" << node.process.log();
  // Frame 0 was consumed above; the reference tracker starts from it again.
  Tracker reference;
  reference.init(box[0].image, box[0].truth);
  for (size_t k = 1; k < box.size(); ++k, ++stamp) {
    SCOPED_TRACE("box frame " + std::to_string(k));
    node.publish(box[k].image, stamp_of(stamp), stamp);
    const auto boundary = node.boundaries.pop(milliseconds(10000));
    const auto state = node.states.pop(milliseconds(10000));
    ASSERT_TRUE(boundary && state) << node.process.log();
    EXPECT_EQ(boundary->header.stamp, stamp_of(stamp));
    const Polygon tracked = ros_node::from_polygon_msg(boundary->polygon);
    EXPECT_LT(mean_boundary_distance(tracked, box[k].truth, 0.5), 3.0);
    const TrackResult expected = reference.track(box[k].image);
    EXPECT_LT(mean_boundary_distance(tracked, expected.boundary, 0.5), 0.01);
    EXPECT_EQ((*state)["event"], "tracked");
  }
  EXPECT_TRUE(node.process.running());
  EXPECT_EQ(node.process.stop(), 0) << node.process.log();
}

}  // namespace
}  // namespace scbt::ros_test

int main(int argc, char** argv) {
  using namespace scbt::ros_test;
  ::testing::InitGoogleTest(&argc, argv);
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], "--node") == 0) g_node_path = argv[i + 1];
  }
  if (g_node_path.empty()) {
    std::cerr << "usage: ros_node_test --node PATH_TO_scbt_node\n";
    return 2;
  }
  if (!on_path("rosmaster")) {
    std::cerr << "SKIPPED: rosmaster not found (install python3-rosmaster: scripts/setup.sh)\n";
    return 77;
  }
  // A master of our own on loopback; ROS_HOME keeps its logs out of the user's ~/.ros.
  namespace fs = std::filesystem;
  const fs::path home = fs::temp_directory_path() / ("scbt_ros_test_" + std::to_string(getpid()));
  fs::create_directories(home);
  g_log_folder = home.string();
  const int port = free_loopback_port();
  const std::string master_uri = "http://127.0.0.1:" + std::to_string(port);
  setenv("ROS_MASTER_URI", master_uri.c_str(), 1);
  setenv("ROS_IP", "127.0.0.1", 1);
  unsetenv("ROS_HOSTNAME");
  setenv("ROS_HOME", home.c_str(), 1);
  setenv("ROS_LOG_DIR", home.c_str(), 1);
  int result = 1;
  {
    ChildProcess master({"rosmaster", "--core", "-p", std::to_string(port)},
                        (home / "rosmaster.log").string());
    ros::init(argc, argv, "scbt_node_test",
              ros::init_options::NoSigintHandler | ros::init_options::AnonymousName);
    if (!wait_until([] { return ros::master::check(); }, std::chrono::milliseconds(20000))) {
      std::cerr << "rosmaster did not come up on " << master_uri << ":\n" << master.log();
      return 1;
    }
    std::cerr << "rosmaster at " << master_uri << ", logs in " << home << "\n";
    ros::AsyncSpinner spinner(2);
    spinner.start();
    result = RUN_ALL_TESTS();
    spinner.stop();
    ros::shutdown();
    master.stop();
  }
  if (result == 0) fs::remove_all(home);
  return result;
}
