#include "scbt/peers/ecc_tracker.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "scbt/testing/peers_test_util.h"

namespace scbt {
namespace {

using testing::mean_vertex_error;
using testing::render_moving_patch;

// The patch moves 2.5 px right, 1.5 px down and turns 0.5 degrees per frame (about 50 px and 10
// degrees over the sequence); the texture is exact and noise-free, so a homography tracker should
// stay within a pixel or so: the bound (1.5 px mean, 3 px worst frame) is a few times the
// resampling/interpolation error, far below the ~60 px the static polygon ends up off.
TEST(EccTracker, FollowsAMovingTexturedPlane) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const testing::MovingPatch scene = render_moving_patch(20, {2.5, 1.5}, 0.5, seed);
    EccTracker tracker;
    tracker.init(scene.frames[0], scene.truth[0]);
    double sum = 0.0;
    for (size_t k = 1; k < scene.frames.size(); ++k) {
      const TrackResult result = tracker.track(scene.frames[k]);
      EXPECT_FALSE(result.held) << "seed " << seed << " frame " << k;
      const double error = mean_vertex_error(result.boundary, scene.truth[k]);
      EXPECT_LT(error, 3.0) << "seed " << seed << " frame " << k;
      EXPECT_GE(result.grouping_ms, 0.0);
      sum += error;
    }
    EXPECT_LT(sum / (scene.frames.size() - 1), 1.5) << "seed " << seed;
  }
}

TEST(EccTracker, HoldsThePreviousPolygonOnAFeaturelessFrame) {
  const testing::MovingPatch scene = render_moving_patch(2, {2.0, 0.0}, 0.0, 5);
  EccTracker tracker;
  tracker.init(scene.frames[0], scene.truth[0]);
  const TrackResult moved = tracker.track(scene.frames[1]);
  ASSERT_FALSE(moved.held);
  const cv::Mat flat(480, 640, CV_8UC3, cv::Scalar(128, 128, 128));
  const TrackResult held = tracker.track(flat);
  EXPECT_TRUE(held.held);
  EXPECT_EQ(held.boundary, moved.boundary);
}

TEST(EccTracker, RejectsBadInputsLikeTheTracker) {
  const testing::MovingPatch scene = render_moving_patch(1, {0.0, 0.0}, 0.0, 2);
  EccTracker tracker;
  EXPECT_THROW(tracker.init(cv::Mat(), scene.truth[0]), std::invalid_argument);
  EXPECT_THROW(tracker.init(scene.frames[0], {{10, 10}, {100, 100}, {100, 10}, {10, 100}}),
               std::invalid_argument);
  EXPECT_THROW(tracker.init(scene.frames[0], {{10, 10}, {700, 10}, {10, 100}}),
               std::invalid_argument);
  EXPECT_THROW(tracker.track(scene.frames[0]), std::logic_error);
  tracker.init(scene.frames[0], scene.truth[0]);
  EXPECT_THROW(tracker.track(cv::Mat(240, 320, CV_8UC3, cv::Scalar::all(0))),
               std::invalid_argument);
  EccTrackerOptions options;
  options.gauss_filter_size = 4;
  EXPECT_THROW(EccTracker{options}, std::invalid_argument);
  options = {};
  options.max_area_factor = 1.0;
  EXPECT_THROW(EccTracker{options}, std::invalid_argument);
}

}  // namespace
}  // namespace scbt
