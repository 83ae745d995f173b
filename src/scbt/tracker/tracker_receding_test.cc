// An object receding from a low-frame-rate camera: a dark bowl inside a bright rim shrinks by
// 6 % of its area per frame, then by 13 %, beyond the area gate (Eq. 2, 0.9). The inner boundary
// then fails the gate while the rim's outer one passes it; a gate that follows the steady
// shrinking (TrackerOptions::gate_sustained_shrink) keeps the inner one. And a plain object that
// recedes by 13 % per frame right after approaching, before any shrinking is sustained: the
// search one gate step smaller follows it.
#include <gtest/gtest.h>

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "scbt/testing/hexagon_scene_test_util.h"
#include "scbt/tracker/tracker.h"

namespace scbt {
namespace {

const Point kCentre(320.0, 240.0);

std::vector<cv::Point> pixels(const Polygon& polygon) {
  std::vector<cv::Point> points;
  for (const Point& p : polygon) points.emplace_back(cvRound(p.x), cvRound(p.y));
  return points;
}

// A textured table with the bowl: its inside (radius `radius`) dark, its rim (to 1.1 x) bright.
cv::Mat render_bowl(double radius, unsigned seed) {
  cv::Mat frame(480, 640, CV_8U);
  cv::RNG rng(seed);
  rng.fill(frame, cv::RNG::UNIFORM, 90, 200);
  cv::GaussianBlur(frame, frame, cv::Size(0, 0), 3.0);
  cv::fillPoly(frame, std::vector<std::vector<cv::Point>>{pixels(hexagon(kCentre, 1.1 * radius))},
               cv::Scalar(230), cv::LINE_AA);
  cv::fillPoly(frame, std::vector<std::vector<cv::Point>>{pixels(hexagon(kCentre, radius))},
               cv::Scalar(20), cv::LINE_AA);
  return frame;
}

// A textured table with a dark hexagon of `radius`, no rim.
cv::Mat render_plain(double radius, unsigned seed) {
  cv::Mat frame(480, 640, CV_8U);
  cv::RNG rng(seed);
  rng.fill(frame, cv::RNG::UNIFORM, 90, 200);
  cv::GaussianBlur(frame, frame, cv::Size(0, 0), 3.0);
  cv::fillPoly(frame, std::vector<std::vector<cv::Point>>{pixels(hexagon(kCentre, radius))},
               cv::Scalar(30), cv::LINE_AA);
  return frame;
}

// The largest mean vertex distance to the hexagon of `radius` that `render` draws, while its
// radius is multiplied by each of `steps` in turn.
using Render = cv::Mat (*)(double radius, unsigned seed);
double worst_error(Render render, double radius, const std::vector<double>& steps,
                   bool gate_sustained_shrink, unsigned seed) {
  TrackerOptions options;
  options.gate_sustained_shrink = gate_sustained_shrink;
  Tracker tracker(options);
  tracker.init(render(radius, seed), hexagon(kCentre, radius));
  double worst = 0.0;
  for (const double step : steps) {
    radius *= step;
    const TrackResult r = tracker.track(render(radius, seed + 1));
    const Polygon truth = hexagon(kCentre, radius);
    double sum = 0.0;
    for (const Point& p : r.boundary) sum += distance_to_boundary(p, truth);
    worst = std::max(worst, sum / static_cast<double>(r.boundary.size()));
  }
  return worst;
}

// The bowl's recession: linear size per frame 0.97 (area 0.94) four times, then 0.935 (area
// 0.874) six times.
double worst_error_receding(bool gate_sustained_shrink, unsigned seed) {
  std::vector<double> steps(4, 0.97);
  steps.insert(steps.end(), 6, 0.935);
  return worst_error(render_bowl, 120.0, steps, gate_sustained_shrink, seed);
}

// The plain hexagon growing by 8 % of its area per frame four times, then shrinking by 13.5 %
// six times.
double worst_error_turning_back(bool gate_sustained_shrink, unsigned seed) {
  std::vector<double> steps(4, 1.04);
  steps.insert(steps.end(), 6, 0.93);
  return worst_error(render_plain, 100.0, steps, gate_sustained_shrink, seed);
}

class RecedingTest : public ::testing::TestWithParam<unsigned> {};

TEST_P(RecedingTest, SteadyShrinkingKeepsTheInnerBoundary) {
  EXPECT_LT(worst_error_receding(true, GetParam()), 2.0);
}

TEST_P(RecedingTest, WithoutFollowingTheShrinkingTheRimIsTaken) {
  EXPECT_GT(worst_error_receding(false, GetParam()), 4.0);
}

TEST_P(RecedingTest, RecedingRightAfterApproachingIsFollowed) {
  EXPECT_LT(worst_error_turning_back(true, GetParam()), 2.0);
}

TEST_P(RecedingTest, WithoutTheShrinkingSearchesTheTurnIsLost) {
  EXPECT_GT(worst_error_turning_back(false, GetParam()), 4.0);
}

INSTANTIATE_TEST_SUITE_P(Seeds, RecedingTest, ::testing::Values(1u, 2u, 3u));

}  // namespace
}  // namespace scbt
