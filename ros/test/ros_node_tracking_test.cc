// scbt_node tracking rendered clips through a real master: every published boundary against the
// clip's truth and against the library's Tracker on the same frames, the stamps, the state.
#include <cmath>
#include <iostream>

#include "node_under_test.h"
#include "scbt/tracker/tracker.h"
#include "scbt_ros/conversions.h"

namespace scbt::ros_test {
namespace {

using std::chrono::milliseconds;
constexpr milliseconds kReplyTimeout(10000);

// Publishes clip[from..] one frame at a time (stamps first_stamp, first_stamp + 1, ...), each
// after the previous one's boundary came back, and checks each boundary: stamped as its image,
// within 3 px of the truth (mean boundary distance) and the same as `reference` tracking the same
// frames (initialised on clip[from - 1] by the caller). Returns the number of held frames.
int play_and_check(NodeUnderTest* node, const std::vector<SceneFrame>& clip, size_t from,
                   int first_stamp, Tracker* reference) {
  int held = 0;
  for (size_t k = from; k < clip.size(); ++k) {
    SCOPED_TRACE(node->name() + " frame " + std::to_string(k));
    const int stamp = first_stamp + static_cast<int>(k - from);
    node->publish(clip[k].image, stamp_of(stamp));
    const auto boundary = node->boundaries.pop(kReplyTimeout);
    const auto state = node->states.pop(kReplyTimeout);
    if (!boundary || !state) {
      ADD_FAILURE() << "no boundary or state; node log:\n" << node->process.log();
      return held;
    }
    EXPECT_EQ(boundary->header.stamp, stamp_of(stamp));
    EXPECT_EQ(boundary->header.frame_id, "scbt_test_camera");
    const Polygon tracked = ros_node::from_polygon_msg(boundary->polygon);
    EXPECT_LT(mean_boundary_distance(tracked, clip[k].truth, 0.5), 3.0);
    const TrackResult expected = reference->track(clip[k].image);
    EXPECT_LT(mean_boundary_distance(tracked, expected.boundary, 0.5), 0.01);
    EXPECT_EQ((*state)["event"], "tracked") << state->dump();
    EXPECT_EQ((*state)["held"], expected.held) << state->dump();
    EXPECT_EQ((*state)["dropped_frames"], 0) << state->dump();
    EXPECT_EQ((*state)["missed_frames"], 0) << state->dump();
    EXPECT_TRUE((*state)["timings_ms"].contains("total")) << state->dump();
    held += expected.held ? 1 : 0;
  }
  return held;
}

TEST(RosNode, TracksRenderedClipsAndIsReinitialisedByMessage) {
  const std::vector<SceneFrame> rim = render_test_clip(SceneShape::kRim, 3, 40);
  ros::param::set("/scbt_clip/init_polygon", flatten(rim[0].truth));
  NodeUnderTest node("scbt_clip");
  ASSERT_TRUE(node.connected());

  // The parameter initialises on the first frame: published back as the boundary.
  node.publish(rim[0].image, stamp_of(0));
  const auto first = node.boundaries.pop(kReplyTimeout);
  const auto first_state = node.states.pop(kReplyTimeout);
  ASSERT_TRUE(first && first_state) << node.process.log();
  EXPECT_EQ(first->header.stamp, stamp_of(0));
  EXPECT_LT(mean_boundary_distance(ros_node::from_polygon_msg(first->polygon), rim[0].truth), 0.01);
  EXPECT_EQ((*first_state)["event"], "initialised");
  Tracker reference;
  reference.init(rim[0].image, rim[0].truth);
  EXPECT_LE(play_and_check(&node, rim, 1, 1, &reference), 2);

  // Another object (another seed and shape) through ~init. The message and the next frame travel
  // on different connections, so the frame is sent again (new stamps) until the node reports it
  // initialised.
  const std::vector<SceneFrame> box = render_test_clip(SceneShape::kBox, 5, 30);
  node.publish_init(box[0].truth);
  bool initialised = false;
  int stamp = 100;
  for (; stamp < 150 && !initialised; ++stamp) {
    node.publish(box[0].image, stamp_of(stamp));
    const auto state = node.states.pop(kReplyTimeout);
    ASSERT_TRUE(state && node.boundaries.pop(kReplyTimeout)) << node.process.log();
    initialised = (*state)["event"] == "initialised";
  }
  ASSERT_TRUE(initialised) << "~init never applied; node log:\n" << node.process.log();
  reference.init(box[0].image, box[0].truth);
  EXPECT_LE(play_and_check(&node, box, 1, stamp, &reference), 2);

  EXPECT_TRUE(node.process.running());
  EXPECT_EQ(node.process.stop(), 0) << node.process.log();
}

// Frames sent as fast as the publisher can: each is either tracked (a boundary and a state),
// replaced by a newer one before the tracker took it (dropped_frames) or lost in ROS's subscriber
// queue before the node saw it (missed_frames, from header.seq); none goes unaccounted or is
// published out of order, and every boundary is near the truth of the frame whose stamp it carries.
TEST(RosNode, FramesItCannotKeepUpWithAreDroppedAndCounted) {
  // Slow motion (under a pixel per frame), so that the boundary is still within reach of the
  // last tracked one after the frames skipped.
  const std::vector<SceneFrame> clip = render_test_clip(SceneShape::kRim, 7, 80, 1200);
  ros::param::set("/scbt_burst/init_polygon", flatten(clip[0].truth));
  NodeUnderTest node("scbt_burst");
  ASSERT_TRUE(node.connected());
  // The first frame alone (initialised on it), so that the node knows where the numbering starts.
  node.publish(clip[0].image, stamp_of(0));
  ASSERT_TRUE(node.states.pop(kReplyTimeout) && node.boundaries.pop(kReplyTimeout));
  const int n = static_cast<int>(clip.size());
  for (int k = 1; k < n; ++k) node.publish(clip[k].image, stamp_of(k));

  // The state's "frame" counts the frames the tracker took (a lost state message would not hide
  // any); wait until every frame is accounted for.
  std::uint64_t taken = 0;
  std::uint64_t dropped = 0;
  std::uint64_t missed = 0;
  while (taken + dropped + missed < static_cast<std::uint64_t>(n)) {
    const auto state = node.states.pop(kReplyTimeout);
    ASSERT_TRUE(state) << taken << " tracked + " << dropped << " dropped + " << missed
                       << " missed of " << n << " frames; node log:\n"
                       << node.process.log();
    taken = (*state)["frame"].get<std::uint64_t>();
    dropped = (*state)["dropped_frames"].get<std::uint64_t>();
    missed = (*state)["missed_frames"].get<std::uint64_t>();
  }
  EXPECT_EQ(taken + dropped + missed, static_cast<std::uint64_t>(n));
  EXPECT_FALSE(node.states.pop(milliseconds(300))) << "more states than frames";

  // Every boundary, in order, near the truth of its frame.
  double last_stamp = stamp_of(0).toSec();
  std::uint64_t boundaries = 1;
  while (const auto boundary = node.boundaries.pop(milliseconds(300))) {
    ++boundaries;
    const double t = boundary->header.stamp.toSec();
    EXPECT_GT(t, last_stamp);
    last_stamp = t;
    const int k = static_cast<int>(std::lround((t - 1000.0) * 30.0));
    ASSERT_TRUE(k >= 0 && k < n) << t;
    EXPECT_LT(mean_boundary_distance(ros_node::from_polygon_msg(boundary->polygon), clip[k].truth),
              3.0)
        << "frame " << k;
  }
  EXPECT_LE(boundaries, taken);
  // The newest frame is never the one dropped: the last frame sent is tracked.
  EXPECT_EQ(last_stamp, stamp_of(n - 1).toSec());
  std::cout << "[ burst    ] " << n << " frames sent at once: " << taken << " tracked, " << dropped
            << " dropped by the node, " << missed << " missed in ROS's queue\n";
  EXPECT_EQ(node.process.stop(), 0) << node.process.log();
}

}  // namespace
}  // namespace scbt::ros_test
