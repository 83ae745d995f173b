// A lost object seen again from another distance or angle: after blank frames it comes back
// elsewhere 1.6 times larger (beyond the moderate scales the search tries by itself), or
// foreshortened (its outline squashed to 0.7 of its height: a rim seen more obliquely). The
// background stays (the scene registers unchanged, so it says nothing of the object's new place or
// size). And a look-alike of the same shape but of another grey, where the object does not come
// back, must not be taken: it is taken only when the appearance check is switched off. A
// container emptied or filled while away (its middle another grey) is still the object.
// Rims and boxes: a random star polygon's narrow spikes are tracked cut short at one size and
// resolved at 1.6 times it, which changes its shape descriptor beyond the match (0.07 against the
// bar of 0.05 for seed 1): a limit of the shape test, not of the search (docs/loss-handling.md).
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <tuple>

#include "scbt/synthetic/scene.h"
#include "scbt/testing/tracker_test_util.h"
#include "scbt/tracker/tracker.h"

namespace scbt {
namespace {

constexpr double kWrongPx = 10.0;
constexpr int kVisible = 20;  // frames before the gap (the first is the initial frame)
constexpr int kGap = 10;      // blank frames
constexpr int kFrames = 55;   // frames in all

enum class Return { kLarger, kFlatter };

struct ReturnRun {
  std::vector<SceneFrame> frames;
  std::vector<TrackResult> results;  // frame 0: the initial frame (default result)
};

Polygon squashed(const Polygon& model, double height) {
  Polygon out;
  for (const Point& p : model) out.emplace_back(p.x, height * p.y);
  return out;
}

// The middle of `outline` (0.7 of its size about its centroid: half its area) painted `level`.
void paint_middle(cv::Mat* image, const Polygon& outline, int level) {
  const Point middle = centroid(outline);
  std::vector<cv::Point> points;
  for (const Point& p : outline) {
    const Point q = middle + (p - middle) * 0.7;
    points.emplace_back(cvRound(q.x), cvRound(q.y));
  }
  cv::fillPoly(*image, std::vector<std::vector<cv::Point>>{points}, cv::Scalar::all(level));
}

// The object drifts, the frames go blank, then the object (or, with `decoy`, a look-alike in a grey
// 100 levels darker; with `other_contents`, the object with its middle 100 levels darker) is seen
// elsewhere, larger or flatter.
ReturnRun render_run(SceneShape shape, std::uint32_t seed, Return how, bool decoy,
                     bool other_contents = false) {
  SceneOptions scene;
  scene.seed = seed;
  scene.shape = shape;
  scene.object_size = 45.0;
  const Polygon model = object_model(scene);
  std::vector<Pose> before =
      linear_motion_path(Pose{Point(200.0, 180.0), 0.0, 1.0}, Point(1.0, 0.5), kVisible);
  std::vector<Pose> after =
      linear_motion_path(Pose{Point(430.0, 290.0), 0.1, how == Return::kLarger ? 1.6 : 1.0},
                         Point(-0.5, 0.5), kFrames - kVisible - kGap);
  const Polygon returning = how == Return::kFlatter ? squashed(model, 0.7) : model;
  std::vector<Pose> all = before;
  all.insert(all.end(), after.begin(), after.end());
  const cv::Mat background = render_background(scene, path_region(model, all));
  SceneOptions look_alike = scene;
  look_alike.object_level = scene.object_level - 100;
  ReturnRun run;
  for (int k = 0; k < kFrames; ++k) {
    if (k < kVisible) {
      run.frames.push_back(render_frame(scene, background, model, before[k], k));
    } else if (k < kVisible + kGap) {
      run.frames.push_back({cv::Mat(scene.size, CV_8UC3, cv::Scalar::all(128)), {}});
    } else {
      run.frames.push_back(render_frame(decoy ? look_alike : scene, background, returning,
                                        after[k - kVisible - kGap], k));
      if (other_contents) {
        paint_middle(&run.frames.back().image, run.frames.back().truth, scene.object_level - 100);
      }
    }
  }
  return run;
}

void track(ReturnRun* run, const TrackerOptions& options = {}) {
  run->results = track_from_truth(run->frames, options);
}

class TrackerReacquireTest
    : public ::testing::TestWithParam<std::tuple<SceneShape, std::uint32_t, Return>> {};

// Lost in the gap, `tracking` again within 5 frames of the return, never on a wrong boundary, then
// a mean error under 2 px.
TEST_P(TrackerReacquireTest, FoundAgainNearerOrAtAnotherAngle) {
  const auto [shape, seed, how] = GetParam();
  ReturnRun run = render_run(shape, seed, how, false);
  track(&run);
  SCOPED_TRACE(describe_run(run.results, run.frames));
  const int back = kVisible + kGap;
  EXPECT_EQ(run.results[back - 1].state, TrackState::kLost);
  int found = -1;
  for (int k = back; k < kFrames; ++k) {
    const TrackResult& r = run.results[k];
    if (r.state != TrackState::kTracking) continue;
    EXPECT_LT(mean_boundary_distance(r.boundary, run.frames[k].truth), kWrongPx) << "frame " << k;
    if (found < 0) found = k;
  }
  ASSERT_GE(found, 0);
  EXPECT_LE(found, back + 5);
  double sum = 0.0;
  for (int k = found; k < kFrames; ++k) {
    sum += mean_boundary_distance(run.results[k].boundary, run.frames[k].truth);
  }
  EXPECT_LT(sum / (kFrames - found), 2.0);
}

// The object comes back with other contents (its middle darker: emptied, or filled) and, larger,
// is found by the view-change match, whose appearance is the band inside the boundary.
TEST_P(TrackerReacquireTest, FoundAgainWithOtherContents) {
  const auto [shape, seed, how] = GetParam();
  ReturnRun run = render_run(shape, seed, how, false, true);
  track(&run);
  SCOPED_TRACE(describe_run(run.results, run.frames));
  int found = -1;
  for (int k = kVisible + kGap; k < kFrames && found < 0; ++k) {
    if (run.results[k].state == TrackState::kTracking) found = k;
  }
  ASSERT_GE(found, 0);
  EXPECT_LE(found, kVisible + kGap + 5);
  EXPECT_LT(mean_boundary_distance(run.results.back().boundary, run.frames.back().truth), 2.0);
}

// The look-alike (the object's outline, larger or flatter, darker inside) is never `tracking`;
// without the appearance check it is, on some frame of the scenes (checked over all of them in
// LookAlikesAreTakenWithoutTheAppearanceCheck).
TEST_P(TrackerReacquireTest, ALookAlikeOfAnotherGreyIsNotTaken) {
  const auto [shape, seed, how] = GetParam();
  ReturnRun run = render_run(shape, seed, how, true);
  track(&run);
  SCOPED_TRACE(describe_run(run.results, run.frames));
  for (int k = kVisible + kGap; k < kFrames; ++k) {
    EXPECT_NE(run.results[k].state, TrackState::kTracking) << "frame " << k;
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, TrackerReacquireTest,
                         ::testing::Combine(::testing::Values(SceneShape::kRim, SceneShape::kBox),
                                            ::testing::Values(1u, 2u),
                                            ::testing::Values(Return::kLarger, Return::kFlatter)));

// The decoy scenes are not passed by construction: with the appearance check off, the search
// takes the look-alike in most of them.
TEST(TrackerReacquireDecoyTest, LookAlikesAreTakenWithoutTheAppearanceCheck) {
  TrackerOptions options;
  options.loss.view_change.min_appearance = 0.0;
  int taken = 0, scenes = 0;
  for (SceneShape shape : {SceneShape::kRim, SceneShape::kBox}) {
    for (std::uint32_t seed : {1u, 2u}) {
      for (Return how : {Return::kLarger, Return::kFlatter}) {
        ReturnRun run = render_run(shape, seed, how, true);
        track(&run, options);
        bool tracked = false;
        for (int k = kVisible + kGap; k < kFrames; ++k) {
          tracked = tracked || run.results[k].state == TrackState::kTracking;
        }
        taken += tracked ? 1 : 0;
        ++scenes;
      }
    }
  }
  EXPECT_GE(taken, scenes / 2) << taken << " of " << scenes;
}

}  // namespace
}  // namespace scbt
