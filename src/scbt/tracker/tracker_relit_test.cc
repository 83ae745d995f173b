// A lost object seen again in another light: after blank frames it is back near where it was, a
// shadow darkening it and its surroundings towards one side (from 0.3 of its width on). Its inside
// level has changed beyond what a re-find may keep, so the search over the frame alone rejects it;
// the object memory sees the lit part of it (its own edges, about half its outline) and vouches
// for the cycle closed along its fit there. Without that, 5 of the 6 scenes stay `uncertain`.
#include <gtest/gtest.h>

#include <algorithm>
#include <tuple>

#include "scbt/geometry/polygon.h"
#include "scbt/synthetic/scene.h"
#include "scbt/testing/tracker_test_util.h"
#include "scbt/tracker/tracker.h"

namespace scbt {
namespace {

constexpr double kWrongPx = 10.0;
constexpr int kVisible = 20;  // frames before the gap (the first is the initial frame)
constexpr int kGap = 10;      // blank frames
constexpr int kFrames = 50;   // frames in all
// The shadow's depth at the object's far side: the share of the light it takes away there.
constexpr double kShadow = 0.6;

struct RelitRun {
  std::vector<SceneFrame> frames;
  std::vector<TrackResult> results;  // frame 0: the initial frame (default result)
};

// Darkens `image` from `from_x` (nothing) to `to_x` and beyond (by kShadow).
void cast_shadow(cv::Mat* image, double from_x, double to_x) {
  for (int y = 0; y < image->rows; ++y) {
    cv::Vec3b* row = image->ptr<cv::Vec3b>(y);
    for (int x = 0; x < image->cols; ++x) {
      const double t = std::clamp((x - from_x) / (to_x - from_x), 0.0, 1.0);
      row[x] *= 1.0 - kShadow * t;
    }
  }
}

RelitRun render_run(SceneShape shape, std::uint32_t seed) {
  SceneOptions scene;
  scene.seed = seed;
  scene.shape = shape;
  scene.object_size = 60.0;
  const Polygon model = object_model(scene);
  std::vector<Pose> before =
      linear_motion_path(Pose{Point(260.0, 220.0), 0.0, 1.0}, Point(1.0, 0.5), kVisible);
  std::vector<Pose> after = linear_motion_path(Pose{Point(285.0, 232.0), 0.05, 1.0},
                                               Point(0.5, 0.3), kFrames - kVisible - kGap);
  std::vector<Pose> all = before;
  all.insert(all.end(), after.begin(), after.end());
  const cv::Mat background = render_background(scene, path_region(model, all));
  RelitRun run;
  for (int k = 0; k < kFrames; ++k) {
    if (k < kVisible) {
      run.frames.push_back(render_frame(scene, background, model, before[k], k));
    } else if (k < kVisible + kGap) {
      run.frames.push_back({cv::Mat(scene.size, CV_8UC3, cv::Scalar::all(128)), {}});
    } else {
      SceneFrame frame = render_frame(scene, background, model, after[k - kVisible - kGap], k);
      const cv::Rect2d box = bounding_box(frame.truth);
      cast_shadow(&frame.image, box.x + 0.3 * box.width, box.x + box.width);
      run.frames.push_back(std::move(frame));
    }
  }
  return run;
}

// The first frame after the gap the run is `tracking` (-1: none); every `tracking` frame after
// the gap must be on the object.
int first_tracking(const RelitRun& run) {
  int found = -1;
  for (int k = kVisible + kGap; k < kFrames; ++k) {
    const TrackResult& r = run.results[k];
    if (r.state != TrackState::kTracking) continue;
    EXPECT_LT(mean_boundary_distance(r.boundary, run.frames[k].truth), kWrongPx) << "frame " << k;
    if (found < 0) found = k;
  }
  return found;
}

class TrackerRelitTest : public ::testing::TestWithParam<std::tuple<SceneShape, std::uint32_t>> {};

TEST_P(TrackerRelitTest, TheMemoryFindsTheObjectInAnotherLight) {
  const auto [shape, seed] = GetParam();
  RelitRun run = render_run(shape, seed);
  TrackerOptions options;
  options.object_memory = true;
  run.results = track_from_truth(run.frames, options);
  SCOPED_TRACE(describe_run(run.results, run.frames));
  EXPECT_EQ(run.results[kVisible + kGap - 1].state, TrackState::kLost);
  const int found = first_tracking(run);
  ASSERT_GE(found, 0);
  EXPECT_LE(found, kVisible + kGap + 5);
}

INSTANTIATE_TEST_SUITE_P(Scenes, TrackerRelitTest,
                         ::testing::Combine(::testing::Values(SceneShape::kRim, SceneShape::kBox),
                                            ::testing::Values(1u, 2u, 3u)));

}  // namespace
}  // namespace scbt
