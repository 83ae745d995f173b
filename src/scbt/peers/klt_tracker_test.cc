#include "scbt/peers/klt_tracker.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "scbt/testing/peers_test_util.h"

namespace scbt {
namespace {

using testing::mean_vertex_error;
using testing::render_moving_patch;

// Same motion as the ecc test (50 px, 10 degrees over 20 frames). Features track to sub-pixel
// accuracy on the noise-free texture and the homography is estimated from frame 1 each time, so
// the polygon should stay within about a pixel: bound 1.5 px mean, 3 px worst frame.
TEST(KltTracker, FollowsAMovingTexturedPlane) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const testing::MovingPatch scene = render_moving_patch(20, {2.5, 1.5}, 0.5, seed);
    KltTracker tracker;
    tracker.init(scene.frames[0], scene.truth[0]);
    EXPECT_GT(tracker.num_features(), 50) << "seed " << seed;
    double sum = 0.0;
    for (size_t k = 1; k < scene.frames.size(); ++k) {
      const TrackResult result = tracker.track(scene.frames[k]);
      EXPECT_FALSE(result.held) << "seed " << seed << " frame " << k;
      const double error = mean_vertex_error(result.boundary, scene.truth[k]);
      EXPECT_LT(error, 3.0) << "seed " << seed << " frame " << k;
      sum += error;
    }
    EXPECT_LT(sum / (scene.frames.size() - 1), 1.5) << "seed " << seed;
  }
}

// Features die when part of the patch is hidden for a frame; re-detection must refill them from
// the current polygon while the estimate stays on track. The patch moves 6 px a frame, so
// features stuck on the static occluder's edge are RANSAC outliers (threshold 3 px).
TEST(KltTracker, RedetectsWhenFeaturesAreLost) {
  const testing::MovingPatch scene = render_moving_patch(12, {6.0, 0.0}, 0.0, 4);
  KltTrackerOptions options;
  options.max_features = 60;
  options.redetect_fraction = 0.9;
  KltTracker tracker(options);
  tracker.init(scene.frames[0], scene.truth[0]);
  for (size_t k = 1; k < scene.frames.size(); ++k) {
    cv::Mat frame = scene.frames[k].clone();
    if (k == 6) {
      // Hide the right half of the patch for one frame: its features fail the checks.
      const cv::Rect2d box = bounding_box(scene.truth[k]);
      frame(cv::Rect(static_cast<int>(box.x + box.width / 2), static_cast<int>(box.y),
                     static_cast<int>(box.width / 2), static_cast<int>(box.height)))
          .setTo(cv::Scalar::all(0));
    }
    const TrackResult result = tracker.track(frame);
    // On the half-hidden frame the far corners are extrapolated from half the patch: 6 px there.
    EXPECT_LT(mean_vertex_error(result.boundary, scene.truth[k]), k == 6 ? 6.0 : 3.0)
        << "frame " << k;
    EXPECT_GE(tracker.num_features(), 20) << "frame " << k;
  }
}

TEST(KltTracker, HoldsThePreviousPolygonOnAFeaturelessFrame) {
  const testing::MovingPatch scene = render_moving_patch(2, {2.0, 0.0}, 0.0, 5);
  KltTracker tracker;
  tracker.init(scene.frames[0], scene.truth[0]);
  const TrackResult moved = tracker.track(scene.frames[1]);
  ASSERT_FALSE(moved.held);
  const cv::Mat flat(480, 640, CV_8UC3, cv::Scalar(128, 128, 128));
  const TrackResult held = tracker.track(flat);
  EXPECT_TRUE(held.held);
  EXPECT_EQ(held.boundary, moved.boundary);
}

TEST(KltTracker, RejectsBadOptions) {
  KltTrackerOptions options;
  options.window_size = 20;
  EXPECT_THROW(KltTracker{options}, std::invalid_argument);
  options = {};
  options.quality_level = 0.0;
  EXPECT_THROW(KltTracker{options}, std::invalid_argument);
  options = {};
  options.redetect_fraction = 1.5;
  EXPECT_THROW(KltTracker{options}, std::invalid_argument);
}

}  // namespace
}  // namespace scbt
