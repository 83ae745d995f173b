// TrackerOptions::smooth_noisy_frames on rendered clips: a rim moving over low-contrast clutter
// through heavy sensor noise is followed more closely when every frame's window is smoothed as
// its noise calls for, and a clip of little noise is tracked exactly as without the smoothing.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <sstream>

#include "scbt/synthetic/scene.h"
#include "scbt/testing/dim_camera_test_util.h"
#include "scbt/tracker/tracker.h"

namespace scbt {
namespace {

constexpr int kFrames = 60;

struct ClipRun {
  double mean_error = 0.0;  // px, mean_boundary_distance to the truth over frames 1..
  std::vector<Polygon> tracked;
};

// A rim over clutter only 12 grey levels from it, plus camera noise of `noise` grey levels.
ClipRun track_clip(double noise, bool smooth, std::uint32_t seed) {
  SceneOptions scene;
  scene.seed = seed;
  scene.min_contrast = 12;
  scene.noise_sigma = 0.0;  // the camera's noise is added below
  MotionOptions motion;
  motion.period = 60;
  const std::vector<SceneFrame> clip = render_clip(scene, smooth_motion_path(motion, kFrames));
  TrackerOptions options;
  options.smooth_noisy_frames = smooth;
  // The searches for a receding object also rescue some of the unsmoothed run's held frames:
  // off in both runs, so that the smoothing alone is compared.
  options.gate_sustained_shrink = false;
  Tracker tracker(options);
  cv::RNG rng(seed);
  ClipRun run;
  for (int k = 0; k < kFrames; ++k) {
    const cv::Mat frame = dim_camera_frame(clip[k].image, 1.0, noise, &rng);
    if (k == 0) {
      tracker.init(frame, clip[0].truth);
      continue;
    }
    const TrackResult result = tracker.track(frame);
    run.mean_error += mean_boundary_distance(result.boundary, clip[k].truth, 0.5);
    run.tracked.push_back(result.boundary);
  }
  run.mean_error /= kFrames - 1;
  return run;
}

TEST(TrackerNoiseTest, HeavyNoiseIsFollowedBetterWithTheSmoothing) {
  double with_sum = 0.0, without_sum = 0.0;
  for (std::uint32_t seed : {1u, 2u, 3u}) {
    const ClipRun with = track_clip(20.0, true, seed);
    const ClipRun without = track_clip(20.0, false, seed);
    std::ostringstream where;
    where << "seed " << seed << ": smoothed mean " << with.mean_error << " px; not smoothed "
          << without.mean_error << " px";
    EXPECT_LT(with.mean_error, 1.0) << where.str();
    with_sum += with.mean_error;
    without_sum += without.mean_error;
  }
  // Noise ridges break the rim into fragments that close neighbouring cycles.
  EXPECT_LT(with_sum, 0.6 * without_sum);
}

TEST(TrackerNoiseTest, LittleNoiseIsTrackedAsWithoutTheSmoothing) {
  for (std::uint32_t seed : {1u, 2u}) {
    const ClipRun with = track_clip(2.0, true, seed);
    const ClipRun without = track_clip(2.0, false, seed);
    EXPECT_EQ(with.tracked, without.tracked) << "seed " << seed;
    EXPECT_LT(with.mean_error, 1.0) << "seed " << seed;
  }
}

}  // namespace
}  // namespace scbt
