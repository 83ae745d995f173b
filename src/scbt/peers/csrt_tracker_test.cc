#include "scbt/peers/csrt_tracker.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "scbt/testing/peers_test_util.h"

namespace scbt {
namespace {

using testing::mean_vertex_error;
using testing::render_moving_patch;

// CSRT only models a box (translation and scale), so the patch only translates here: 3 px right
// and 2 px down per frame, ~55 px over 20 frames. CSRT's box is integer and its scale search
// steps by about 2 % per frame, which can move the corners of a 160x120 patch by a couple of
// pixels: bound 4 px mean, 8 px worst frame (the static polygon is ~55 px off by the end).
TEST(CsrtTracker, FollowsAMovingTexturedPlane) {
  for (unsigned seed = 1; seed <= 2; ++seed) {
    const testing::MovingPatch scene = render_moving_patch(20, {3.0, 2.0}, 0.0, seed);
    CsrtTracker tracker;
    tracker.init(scene.frames[0], scene.truth[0]);
    double sum = 0.0;
    for (size_t k = 1; k < scene.frames.size(); ++k) {
      const TrackResult result = tracker.track(scene.frames[k]);
      EXPECT_FALSE(result.held) << "seed " << seed << " frame " << k;
      const double error = mean_vertex_error(result.boundary, scene.truth[k]);
      EXPECT_LT(error, 8.0) << "seed " << seed << " frame " << k;
      sum += error;
    }
    EXPECT_LT(sum / (scene.frames.size() - 1), 4.0) << "seed " << seed;
  }
}

TEST(CsrtTracker, AcceptsGreyFramesAndRejectsBadInputs) {
  const testing::MovingPatch scene = render_moving_patch(3, {2.0, 1.0}, 0.0, 3);
  CsrtTracker tracker;
  EXPECT_THROW(tracker.track(scene.frames[0]), std::logic_error);
  EXPECT_THROW(tracker.init(scene.frames[0], {{1, 1}, {2, 2}}), std::invalid_argument);
  cv::Mat gray;
  cv::cvtColor(scene.frames[0], gray, cv::COLOR_BGR2GRAY);
  tracker.init(gray, scene.truth[0]);
  cv::cvtColor(scene.frames[1], gray, cv::COLOR_BGR2GRAY);
  const TrackResult result = tracker.track(gray);
  EXPECT_LT(mean_vertex_error(result.boundary, scene.truth[1]), 8.0);  // the worst-frame bound
  CsrtTrackerOptions options;
  options.max_area_factor = 0.5;
  EXPECT_THROW(CsrtTracker{options}, std::invalid_argument);
}

}  // namespace
}  // namespace scbt
