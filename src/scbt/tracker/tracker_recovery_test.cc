// A camera swing moves the whole picture farther than the search band in one frame: without
// recovery the boundary is held where it was; with recovery by image motion it is found again.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <tuple>

#include "scbt/testing/hexagon_scene_test_util.h"
#include "scbt/tracker/tracker.h"

namespace scbt {
namespace {

// The 640x480 view of the scene whose top-left corner is at `corner`, grey or BGR (the tracker
// keeps its reference window differently for the two: a copy of a grey frame's view, its own
// conversion of a colour one).
cv::Mat view(const cv::Mat& scene, cv::Point corner, bool colour) {
  const cv::Mat grey = scene(cv::Rect(corner, cv::Size(640, 480))).clone();
  if (!colour) return grey;
  cv::Mat bgr;
  cv::cvtColor(grey, bgr, cv::COLOR_GRAY2BGR);
  return bgr;
}

double mean_vertex_distance(const Polygon& tracked, const Polygon& truth) {
  double sum = 0.0;
  for (const Point& p : tracked) sum += distance_to_boundary(p, truth);
  return sum / static_cast<double>(tracked.size());
}

class RecoveryTest : public ::testing::TestWithParam<std::tuple<int, bool>> {};

TEST_P(RecoveryTest, FollowsACameraSwingBeyondTheBand) {
  const int seed = std::get<0>(GetParam());
  const bool colour = std::get<1>(GetParam());
  const cv::Mat scene = render_hexagon_scene(100 + seed);
  const cv::Point start(160, 120);
  // The picture jumps by 34..46 px: far beyond the 20 px band around the previous boundary.
  const cv::Point swing(-(30 + 4 * seed), 20 + 2 * seed);
  const Polygon truth_before = hexagon({480.0 - start.x, 360.0 - start.y}, 70);
  Polygon truth_after = truth_before;
  for (Point& p : truth_after) p -= Point(swing.x, swing.y);

  for (const bool recover : {false, true}) {
    TrackerOptions options;
    options.recover_by_motion = recover;
    Tracker tracker(options);
    tracker.init(view(scene, start, colour), truth_before);
    const TrackResult steady = tracker.track(view(scene, start, colour));
    ASSERT_FALSE(steady.held);
    // Two steady frames: the reference window handed over on the first is reused on the second.
    ASSERT_FALSE(tracker.track(view(scene, start, colour)).held);
    const TrackResult moved = tracker.track(view(scene, start + swing, colour));
    if (recover) {
      EXPECT_FALSE(moved.held);
      EXPECT_TRUE(moved.recovered);
      EXPECT_EQ(moved.step, SearchStep::kImageMotion);
      EXPECT_LT(mean_vertex_distance(moved.boundary, truth_after), 2.0);
    } else {
      EXPECT_TRUE(moved.held);
      EXPECT_FALSE(moved.recovered);
      EXPECT_EQ(moved.step, SearchStep::kNone);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(SeedsGreyAndColour, RecoveryTest,
                         ::testing::Combine(::testing::Range(0, 4), ::testing::Bool()));

}  // namespace
}  // namespace scbt
