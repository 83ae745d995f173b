// AdaptiveThresholdOptions::retry_weak_frames on rendered clips: a dim frame whose boundary falls
// below EDLines' published thresholds is searched again with thresholds adapted to it, a
// well-exposed frame is tracked exactly as without the retry, and the retry does not take a faint
// cycle of another shape.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "scbt/synthetic/scene.h"
#include "scbt/testing/dim_camera_test_util.h"
#include "scbt/tracker/option_table.h"
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
  // The retry alone: scaling the thresholds to the frame's contrast would find the dim rim too.
  // Without that scaling, searching where the rim moved adapts the thresholds to the rim itself
  // (about 12, against 4 beside it), too high for its faint step at 8 % of the light (seed 1).
  options.exposure.normalize = false;
  set_tracker_option(&options, "predict_motion", false);
  // ... and smoothing every noisy frame would find the noisy rim without the retry.
  options.smooth_noisy_frames = false;
  Tracker tracker(options);
  cv::RNG rng(seed);
  ClipRun run;
  for (int k = 0; k < kFrames; ++k) {
    const cv::Mat frame = dim_camera_frame(clip[k].image, brightness, noise, &rng);
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

// A dark square on grey moves for 10 frames, then is blurred (sigma 8 px: its edge falls below the
// published thresholds) with a thin outline of a rectangle of similar area but another shape
// (aspect 1.46) drawn over it.
std::vector<cv::Mat> square_blurred_under_a_rectangle(std::vector<Polygon>* square_outline) {
  std::vector<cv::Mat> frames;
  for (int k = 0; k < 16; ++k) {
    cv::Mat frame(240, 320, CV_8UC1, cv::Scalar(128));
    const double cx = 150.0 + std::min(k, 9), cy = 120.0;
    const Polygon square = {
        {cx - 30, cy - 30}, {cx + 30, cy - 30}, {cx + 30, cy + 30}, {cx - 30, cy + 30}};
    std::vector<cv::Point> corners;
    for (const Point& p : square) corners.emplace_back(cvRound(p.x), cvRound(p.y));
    cv::fillConvexPoly(frame, corners, cv::Scalar(60));
    if (k < 10) {
      square_outline->push_back(square);
    } else {
      cv::GaussianBlur(frame, frame, cv::Size(), 8.0);
      cv::rectangle(frame, cv::Point(cvRound(cx - 35), cvRound(cy - 24)),
                    cv::Point(cvRound(cx + 35), cvRound(cy + 24)), cv::Scalar(100), 1);
    }
    frames.push_back(frame);
  }
  return frames;
}

// Lowered thresholds close many more cycles: a retry's boundary must also keep the reference shape
// (LossOptions::match_shape_distance), as a re-found object's must. Adapting on every frame, the
// rectangle is found and tracked (so it is there to find); the weak-frame retry does not take it
// (without the shape test it did, on every frame after the square).
TEST(TrackerWeakFramesTest, AFaintCycleOfAnotherShapeIsNotTakenByTheRetry) {
  std::vector<Polygon> square;
  const std::vector<cv::Mat> frames = square_blurred_under_a_rectangle(&square);
  auto tracked_after_the_square = [&](const TrackerOptions& options) {
    Tracker tracker(options);
    tracker.init(frames[0], square[0]);
    int tracked = 0;
    for (size_t k = 1; k < frames.size(); ++k) {
      const TrackResult r = tracker.track(frames[k]);
      if (k < square.size()) {
        EXPECT_EQ(r.state, TrackState::kTracking) << "frame " << k;
        EXPECT_LT(mean_boundary_distance(r.boundary, square[k]), 1.5) << "frame " << k;
      } else {
        tracked += r.state == TrackState::kTracking ? 1 : 0;
      }
    }
    return tracked;
  };
  // The thresholds as published, not scaled to this flat grey frame's low contrast
  // (ExposureOptions), under which the first search itself sees the rectangle.
  TrackerOptions every_frame;
  every_frame.exposure.normalize = false;
  every_frame.adaptive_thresholds.enabled = true;
  // What acts only with the adaptive thresholds off.
  every_frame.smooth_noisy_frames = false;
  every_frame.adaptive_thresholds.retry_weak_frames = false;
  EXPECT_GT(tracked_after_the_square(every_frame), 0);
  TrackerOptions weak_frames;
  weak_frames.exposure.normalize = false;
  ASSERT_TRUE(weak_frames.adaptive_thresholds.retry_weak_frames);
  EXPECT_EQ(tracked_after_the_square(weak_frames), 0);
}

}  // namespace
}  // namespace scbt
