// A cut of the view (a jump in the video): the rendered scene is seen again through a similarity
// (moved, and scaled or not), with or without a look-alike of the object, stretched, painted where
// the object was. The tracker must not report a wrong boundary as tracked, must declare the object
// lost and find it again where the cut put it.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <tuple>

#include "scbt/synthetic/scene.h"
#include "scbt/testing/tracker_test_util.h"
#include "scbt/tracker/tracker.h"

namespace scbt {
namespace {

constexpr double kWrongPx = 10.0;
constexpr int kCut = 15;     // the first frame of the second view
constexpr int kFrames = 45;  // frames in all

struct CutRun {
  std::vector<SceneFrame> frames;
  std::vector<TrackResult> results;  // frame 0: the initial frame (default result)
};

Polygon transformed(const cv::Matx23d& m, const Polygon& polygon) {
  Polygon out;
  for (const Point& p : polygon) {
    out.emplace_back(m(0, 0) * p.x + m(0, 1) * p.y + m(0, 2),
                     m(1, 0) * p.x + m(1, 1) * p.y + m(1, 2));
  }
  return out;
}

// From frame kCut on, every frame is the rendered one seen through `scale` about the frame's
// centre and moved by `shift` (uniform grey beyond the rendered frame: a reflected border would
// hold mirror images of the object); with `decoy`, the last outline before the cut, stretched (1.25
// x wide, 0.9 x high), is painted in the object's grey where the object was.
CutRun track_cut_scene(SceneShape shape, std::uint32_t seed, double scale, Point shift,
                       bool decoy) {
  SceneOptions scene;
  scene.seed = seed;
  scene.shape = shape;
  scene.object_size = 50.0;
  const std::vector<Pose> poses =
      linear_motion_path(Pose{Point(260.0, 220.0), 0.0, 1.0}, Point(1.0, 0.5), kFrames);
  CutRun run{render_clip(scene, poses), {}};
  const Point centre(320.0, 240.0);
  const cv::Matx23d view(scale, 0.0, centre.x * (1.0 - scale) + shift.x, 0.0, scale,
                         centre.y * (1.0 - scale) + shift.y);
  Polygon look_alike;
  const Point last = centroid(run.frames[kCut - 1].truth);
  for (const Point& p : run.frames[kCut - 1].truth) {
    look_alike.emplace_back(last.x + 1.25 * (p.x - last.x), last.y + 0.9 * (p.y - last.y));
  }
  for (int k = kCut; k < kFrames; ++k) {
    SceneFrame& f = run.frames[k];
    cv::Mat warped;
    cv::warpAffine(f.image, warped, cv::Mat(view), f.image.size(), cv::INTER_LINEAR,
                   cv::BORDER_CONSTANT, cv::Scalar::all(128));
    f.image = warped;
    f.truth = transformed(view, f.truth);
    if (decoy) {
      std::vector<cv::Point> points;
      for (const Point& p : look_alike) points.emplace_back(cvRound(p.x), cvRound(p.y));
      cv::fillPoly(f.image, std::vector<std::vector<cv::Point>>{points},
                   cv::Scalar::all(scene.object_level), cv::LINE_AA);
    }
  }
  run.results = track_from_truth(run.frames);
  return run;
}

// Lost within a few frames of the cut, never `tracking` on a wrong boundary, and `tracking`
// again on the object within `within` frames of the cut, then a mean error under 2 px.
void expect_lost_and_found(const CutRun& run, int within) {
  SCOPED_TRACE(describe_run(run.results, run.frames));
  int first_lost = -1, found = -1;
  for (int k = kCut; k < kFrames; ++k) {
    const TrackResult& r = run.results[k];
    const double error = mean_boundary_distance(r.boundary, run.frames[k].truth);
    if (r.state == TrackState::kLost && first_lost < 0) first_lost = k;
    if (r.state == TrackState::kTracking) {
      EXPECT_LT(error, kWrongPx) << "tracking a wrong boundary at frame " << k;
      if (found < 0) found = k;
    }
  }
  ASSERT_GE(first_lost, 0);
  EXPECT_LE(first_lost, kCut + 6);
  ASSERT_GE(found, 0);
  EXPECT_LE(found, kCut + within);
  double sum = 0.0;
  for (int k = found; k < kFrames; ++k) {
    sum += mean_boundary_distance(run.results[k].boundary, run.frames[k].truth);
  }
  EXPECT_LT(sum / (kFrames - found), 2.0);
}

class TrackerCutTest : public ::testing::TestWithParam<std::tuple<SceneShape, std::uint32_t>> {};

TEST_P(TrackerCutTest, ALookAlikeLeftWhereTheObjectWasIsNotTracked) {
  const auto [shape, seed] = GetParam();
  expect_lost_and_found(track_cut_scene(shape, seed, 1.0, Point(140.0, 60.0), true), 10);
}

// The scene (object and surroundings) comes back at 0.6 or 1.5 times its size: outside the scales
// the search tries by itself, found through the registration of the scene (scene_keyframes.h).
TEST_P(TrackerCutTest, TheObjectComesBackSmallerOrLarger) {
  const auto [shape, seed] = GetParam();
  expect_lost_and_found(track_cut_scene(shape, seed, 0.6, Point(100.0, 40.0), false), 10);
  expect_lost_and_found(track_cut_scene(shape, seed, 1.5, Point(-40.0, 20.0), false), 10);
}

INSTANTIATE_TEST_SUITE_P(Shapes, TrackerCutTest,
                         ::testing::Combine(::testing::Values(SceneShape::kRim, SceneShape::kBox,
                                                              SceneShape::kPolygon),
                                            ::testing::Values(1u, 2u, 3u, 4u, 5u, 6u, 7u, 8u)));

}  // namespace
}  // namespace scbt
