#include "scbt/peers/polygon_tracker.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

#include "scbt/testing/peers_test_util.h"

namespace scbt {
namespace {

TEST(PolygonTracker, FactoryBuildsEveryListedTracker) {
  const std::vector<std::string> names = polygon_tracker_names();
  for (const char* expected : {"scbt", "ecc", "klt", "csrt", "rrc", "static"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
  }
  const testing::MovingPatch scene = testing::render_moving_patch(2, {2.0, 1.0}, 0.0, 9);
  for (const std::string& name : names) {
    std::unique_ptr<PolygonTracker> tracker = make_polygon_tracker(name);
    ASSERT_TRUE(tracker) << name;
    EXPECT_THROW(tracker->init(scene.frames[0], {{1, 1}, {5, 5}}), std::invalid_argument) << name;
    tracker->init(scene.frames[0], scene.truth[0]);
    const TrackResult result = tracker->track(scene.frames[1]);
    EXPECT_GE(result.boundary.size(), 3u) << name;
  }
  EXPECT_THROW(make_polygon_tracker("esm"), std::invalid_argument);
}

// "bdsp", scbt's earlier name in `scbt eval`, still names it.
TEST(PolygonTracker, BdspIsAnAliasOfScbt) {
  EXPECT_EQ(canonical_polygon_tracker_name("bdsp"), "scbt");
  EXPECT_EQ(canonical_polygon_tracker_name("klt"), "klt");
  const std::vector<std::string> names = polygon_tracker_names();
  EXPECT_EQ(std::find(names.begin(), names.end(), "bdsp"), names.end());
  const testing::MovingPatch scene = testing::render_moving_patch(2, {2.0, 1.0}, 0.0, 9);
  std::unique_ptr<PolygonTracker> tracker = make_polygon_tracker("bdsp");
  tracker->init(scene.frames[0], scene.truth[0]);
  EXPECT_GE(tracker->track(scene.frames[1]).boundary.size(), 3u);
}

// The floor: the initial polygon, held, whatever the frames show. On a moving scene it is far
// off, which is what every real tracker's test bound is measured against.
TEST(PolygonTracker, StaticHoldsTheInitialPolygon) {
  const testing::MovingPatch scene = testing::render_moving_patch(20, {2.5, 1.5}, 0.5, 1);
  std::unique_ptr<PolygonTracker> tracker = make_polygon_tracker("static");
  tracker->init(scene.frames[0], scene.truth[0]);
  TrackResult result;
  for (size_t k = 1; k < scene.frames.size(); ++k) {
    result = tracker->track(scene.frames[k]);
    EXPECT_TRUE(result.held);
    EXPECT_EQ(result.boundary, scene.truth[0]);
  }
  EXPECT_GT(testing::mean_vertex_error(result.boundary, scene.truth.back()), 40.0);
}

}  // namespace
}  // namespace scbt
