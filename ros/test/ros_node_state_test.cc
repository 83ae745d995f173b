// scbt_node's ~state through a real master: the tracker's state and confidence frame by frame
// while the object is hidden and comes back (a rendered gap scene), and initialisation from a box
// (~init_box parameter and message, Tracker::init_from_box).
#include <iostream>

#include "node_under_test.h"
#include "scbt/synthetic/gap_scene.h"
#include "scbt/tracker/tracker.h"
#include "scbt_ros/conversions.h"

namespace scbt::ros_test {
namespace {

using std::chrono::milliseconds;
constexpr milliseconds kReplyTimeout(10000);

struct Reply {
  Polygon boundary;
  nlohmann::json state;
};

// Publishes one frame and waits for its boundary and state (stamped as the frame).
std::optional<Reply> track_one(NodeUnderTest* node, const cv::Mat& image, int stamp) {
  node->publish(image, stamp_of(stamp));
  const auto boundary = node->boundaries.pop(kReplyTimeout);
  const auto state = node->states.pop(kReplyTimeout);
  if (!boundary || !state) {
    ADD_FAILURE() << "no boundary or state; node log:\n" << node->process.log();
    return std::nullopt;
  }
  EXPECT_EQ(boundary->header.stamp, stamp_of(stamp));
  return Reply{ros_node::from_polygon_msg(boundary->polygon), *state};
}

// An occluder slides over the object, hides it for 10 frames and slides off: ~state must carry
// the library tracker's state and confidence on every frame -- `lost` during the gap, `tracking`
// again once the object is back -- with the boundary the library gives.
TEST(RosNode, StateAndConfidenceFollowTheTrackerThroughAGap) {
  SceneOptions scene;
  scene.seed = 1;
  scene.shape = SceneShape::kRim;
  scene.object_size = 60.0;
  GapSceneOptions gap;
  gap.kind = GapKind::kOccluder;
  gap.gap = 10;
  const GapScene clip = render_gap_scene(scene, gap);
  ros::param::set("/scbt_gap/init_polygon", flatten(clip.frames[0].truth));
  NodeUnderTest node("scbt_gap");
  ASSERT_TRUE(node.connected());
  const auto first = track_one(&node, clip.frames[0].image, 0);
  ASSERT_TRUE(first);
  EXPECT_EQ(first->state["event"], "initialised");
  EXPECT_EQ(first->state["state"], "tracking");

  Tracker reference;
  reference.init(clip.frames[0].image, clip.frames[0].truth);
  const int n = static_cast<int>(clip.frames.size());
  int lost_while_hidden = 0;
  int first_tracking_after = -1;
  int reacquired = 0;
  std::string trace;
  for (int k = 1; k < n; ++k) {
    SCOPED_TRACE("frame " + std::to_string(k));
    const auto reply = track_one(&node, clip.frames[k].image, k);
    ASSERT_TRUE(reply);
    const TrackResult expected = reference.track(clip.frames[k].image);
    const nlohmann::json& state = reply->state;
    EXPECT_EQ(state["event"], "tracked") << state.dump();
    EXPECT_EQ(state["state"], to_string(expected.state)) << state.dump();
    EXPECT_NEAR(state["confidence"].get<double>(), expected.confidence, 1e-9) << state.dump();
    const auto confidence = node.confidences.pop(kReplyTimeout);
    ASSERT_TRUE(confidence) << "no ~confidence";
    EXPECT_EQ(*confidence, static_cast<float>(expected.confidence));
    EXPECT_EQ(state["held"], expected.held) << state.dump();
    EXPECT_EQ(state["reacquired"], expected.reacquired) << state.dump();
    EXPECT_LT(mean_boundary_distance(reply->boundary, expected.boundary, 0.5), 0.01);
    for (const char* t : {"line", "grouping", "total", "latency", "search"}) {
      EXPECT_TRUE(state["timings_ms"].contains(t)) << t << " missing: " << state.dump();
    }
    const std::string s = state["state"].get<std::string>();
    trace += std::to_string(k) + (clip.hidden[k] ? "H" : "") + ":" + s[0] + " ";
    if (clip.hidden[k] && s == "lost") ++lost_while_hidden;
    if (k >= clip.first_back && first_tracking_after < 0 && s == "tracking") {
      first_tracking_after = k;
    }
    if (state["reacquired"] == true) ++reacquired;
  }
  std::cout << "[ gap      ] states: " << trace << "\n";
  // /diagnostics: ERROR while lost, OK once tracking again (published when the level changes).
  bool error_while_lost = false;
  bool ok_after = false;
  while (const auto status = node.diagnostics.pop(milliseconds(error_while_lost ? 200 : 3000))) {
    if (status->level == diagnostic_msgs::DiagnosticStatus::ERROR &&
        status->message.rfind("lost", 0) == 0) {
      error_while_lost = true;
    }
    if (error_while_lost && status->level == diagnostic_msgs::DiagnosticStatus::OK) ok_after = true;
  }
  EXPECT_TRUE(error_while_lost);
  EXPECT_TRUE(ok_after);
  EXPECT_GT(lost_while_hidden, 0) << trace;
  ASSERT_GE(first_tracking_after, 0) << trace;
  EXPECT_LT(first_tracking_after - clip.first_back, 5) << trace;
  EXPECT_GT(reacquired, 0) << trace;
  // Once tracking again, on the object.
  EXPECT_LT(mean_boundary_distance(reference.boundary(), clip.frames[n - 1].truth), 3.0);
  EXPECT_EQ(node.process.stop(), 0) << node.process.log();
}

// `_init_box:=[x, y, w, h]` on the command line, then another object through ~init_box: each time
// the boundary published for the frame the box was applied to is the most salient closed boundary
// inside it (as Tracker::init_from_box finds it), the object's outline, and tracking goes on.
TEST(RosNode, InitialisedFromABoxByParameterAndByMessage) {
  const std::vector<SceneFrame> rim = render_test_clip(SceneShape::kRim, 3, 12);
  const cv::Rect rim_box = loose_box(rim[0].truth);
  NodeUnderTest node("scbt_box", {"_init_box:=[" + std::to_string(rim_box.x) + ", " +
                                  std::to_string(rim_box.y) + ", " + std::to_string(rim_box.width) +
                                  ", " + std::to_string(rim_box.height) + "]"});
  ASSERT_TRUE(node.connected());
  Tracker reference;
  const auto first = track_one(&node, rim[0].image, 0);
  ASSERT_TRUE(first);
  EXPECT_EQ(first->state["event"], "initialised") << first->state.dump();
  const Polygon expected = reference.init_from_box(rim[0].image, rim_box);
  EXPECT_LT(mean_boundary_distance(first->boundary, expected, 0.5), 0.01);
  EXPECT_LT(mean_boundary_distance(first->boundary, rim[0].truth), 1.5);
  for (int k = 1; k < static_cast<int>(rim.size()); ++k) {
    const auto reply = track_one(&node, rim[k].image, k);
    ASSERT_TRUE(reply);
    EXPECT_LT(mean_boundary_distance(reply->boundary, rim[k].truth), 3.0) << "frame " << k;
    EXPECT_EQ(reply->state["state"], "tracking") << reply->state.dump();
  }

  // The message and the next frame travel on different connections: the frame is sent again
  // (new stamps) until the node reports the box applied.
  const std::vector<SceneFrame> box = render_test_clip(SceneShape::kBox, 5, 8);
  const cv::Rect box_box = loose_box(box[0].truth);
  node.publish_init_box(box_box);
  std::optional<Reply> applied;
  for (int stamp = 100; stamp < 150 && !applied; ++stamp) {
    auto reply = track_one(&node, box[0].image, stamp);
    ASSERT_TRUE(reply);
    if (reply->state["event"] == "initialised") applied = reply;
  }
  ASSERT_TRUE(applied) << "~init_box never applied; node log:\n" << node.process.log();
  EXPECT_LT(mean_boundary_distance(applied->boundary,
                                   reference.init_from_box(box[0].image, box_box), 0.5),
            0.01);
  EXPECT_LT(mean_boundary_distance(applied->boundary, box[0].truth), 1.5);
  for (int k = 1; k < static_cast<int>(box.size()); ++k) {
    const auto reply = track_one(&node, box[k].image, 200 + k);
    ASSERT_TRUE(reply);
    EXPECT_LT(mean_boundary_distance(reply->boundary, box[k].truth), 3.0) << "frame " << k;
  }
  EXPECT_EQ(node.process.stop(), 0) << node.process.log();
}

}  // namespace
}  // namespace scbt::ros_test
