// AdaptiveThresholdOptions::retry_weak_frames on rendered clips: a dim frame whose boundary falls
// below EDLines' published thresholds is searched again with thresholds adapted to it, and a
// well-exposed frame is tracked exactly as without the retry.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <sstream>

#include "scbt/synthetic/scene.h"
#include "scbt/tracker/tracker.h"

namespace scbt {
namespace {

constexpr int kFrames = 40;

struct ClipRun {
  double mean_error = 0.0;  // px, mean_boundary_distance to the truth over frames 1..
  int held = 0;
  std::vector<Polygon> tracked;
};

// A clip of a rim moving smoothly over clutter, every frame's values times `brightness` plus
// Gaussian noise of `noise` grey levels (a dim scene with gain noise), tracked from the truth.
ClipRun track_clip(double brightness, double noise, bool retry_weak_frames, std::uint32_t seed) {
  SceneOptions scene;
  scene.seed = seed;
  MotionOptions motion;
  motion.period = 60;
  const std::vector<SceneFrame> clip = render_clip(scene, smooth_motion_path(motion, kFrames));
  TrackerOptions options;
  options.adaptive_thresholds.retry_weak_frames = retry_weak_frames;
  Tracker tracker(options);
  cv::RNG rng(seed);
  ClipRun run;
  for (int k = 0; k < kFrames; ++k) {
    cv::Mat frame;
    clip[k].image.convertTo(frame, CV_32F, brightness);
    cv::Mat gain_noise(frame.size(), frame.type());
    rng.fill(gain_noise, cv::RNG::NORMAL, 0.0, noise);
    frame += gain_noise;
    frame.convertTo(frame, CV_8U);  // saturates to 0..255
    if (k == 0) {
      tracker.init(frame, clip[0].truth);
      continue;
    }
    const TrackResult result = tracker.track(frame);
    run.held += result.held ? 1 : 0;
    run.mean_error += mean_boundary_distance(result.boundary, clip[k].truth, 0.5);
    run.tracked.push_back(result.boundary);
  }
  run.mean_error /= kFrames - 1;
  return run;
}

TEST(TrackerWeakFramesTest, DimClipIsFollowedOnlyWithTheRetry) {
  for (std::uint32_t seed : {1u, 2u}) {
    const ClipRun with = track_clip(0.08, 1.0, true, seed);
    const ClipRun without = track_clip(0.08, 1.0, false, seed);
    std::ostringstream where;
    where << "seed " << seed << ": with the retry mean " << with.mean_error << " px, held "
          << with.held << "; without mean " << without.mean_error << " px, held " << without.held;
    // At 8 % of the light the rim's step (at least 45 grey levels lit) is a few grey levels per
    // pixel: below the published gradient threshold, which then finds no closed boundary.
    EXPECT_LT(with.mean_error, 2.0) << where.str();
    EXPECT_LT(with.held, 4) << where.str();
    EXPECT_GT(without.mean_error, 2.0 * with.mean_error) << where.str();
  }
}

TEST(TrackerWeakFramesTest, NoisyClipIsFollowedBetterWithTheRetry) {
  // Half the light and noise of 20 grey levels: the rim breaks into fragments that often close
  // no admissible cycle; the retry smooths the window as the noise calls for.
  const ClipRun with = track_clip(0.5, 20.0, true, 4);
  const ClipRun without = track_clip(0.5, 20.0, false, 4);
  std::ostringstream where;
  where << "with the retry mean " << with.mean_error << " px, held " << with.held
        << "; without mean " << without.mean_error << " px, held " << without.held;
  EXPECT_LT(with.mean_error, 1.0) << where.str();
  EXPECT_LT(with.mean_error, 0.75 * without.mean_error) << where.str();
  EXPECT_LT(with.held, without.held) << where.str();
}

TEST(TrackerWeakFramesTest, WellExposedClipIsTrackedExactlyAsWithoutTheRetry) {
  const ClipRun with = track_clip(1.0, 0.0, true, 3);
  const ClipRun without = track_clip(1.0, 0.0, false, 3);
  ASSERT_EQ(with.tracked.size(), without.tracked.size());
  for (size_t k = 0; k < with.tracked.size(); ++k) {
    EXPECT_EQ(with.tracked[k], without.tracked[k]) << "frame " << k + 1;
  }
  EXPECT_LT(with.mean_error, 1.5);
}

}  // namespace
}  // namespace scbt
