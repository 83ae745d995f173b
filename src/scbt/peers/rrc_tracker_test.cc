#include "scbt/peers/rrc_tracker.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <random>
#include <stdexcept>

#include "scbt/testing/peers_test_util.h"

namespace scbt {
namespace {

Polygon shifted(const Polygon& polygon, const Point& by) {
  Polygon out;
  for (const Point& p : polygon) out.push_back(p + by);
  return out;
}

// Mean distance from the vertices of `from` to the outline of `to`.
double mean_distance_to(const Polygon& from, const Polygon& to) {
  double sum = 0.0;
  for (const Point& p : from) sum += distance_to_boundary(p, to);
  return sum / from.size();
}

// A dark irregular hexagon on a bright, mildly textured background, moved a few pixels a frame:
// its outline is a closed chain of high-contrast straight edges, which the ratio contour must
// close (every detected side joined across the corners). The found polygon must hug the true
// outline (within 2 px on average both ways: EDLines segments lie on the edges to about a pixel
// and the corner gap fillers cut the corners by about as much) and enclose nearly its area.
TEST(RrcTracker, FindsAMovingClosedOutline) {
  const Polygon hexagon = {{220, 160}, {330, 140}, {420, 200}, {400, 310}, {290, 340}, {210, 270}};
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 4.0);
  RrcTracker tracker;
  for (int k = 0; k < 6; ++k) {
    const Polygon truth = shifted(hexagon, {4.0 * k, -2.0 * k});
    cv::Mat frame(480, 640, CV_8UC1);
    for (int y = 0; y < frame.rows; ++y) {
      for (int x = 0; x < frame.cols; ++x) {
        frame.at<uchar>(y, x) = cv::saturate_cast<uchar>(200 + noise(rng));
      }
    }
    std::vector<cv::Point> outline;
    for (const Point& p : truth) outline.emplace_back(cvRound(p.x), cvRound(p.y));
    cv::fillPoly(frame, std::vector<std::vector<cv::Point>>{outline}, cv::Scalar(50), cv::LINE_AA);
    if (k == 0) {
      tracker.init(frame, truth);
      continue;
    }
    const TrackResult result = tracker.track(frame);
    ASSERT_FALSE(result.held) << "frame " << k;
    EXPECT_GE(result.num_kept, 6) << "frame " << k;
    EXPECT_LT(mean_distance_to(result.boundary, truth), 2.0) << "frame " << k;
    EXPECT_LT(mean_distance_to(truth, result.boundary), 2.0) << "frame " << k;
    EXPECT_NEAR(area(result.boundary) / area(truth), 1.0, 0.05) << "frame " << k;
    EXPECT_GT(result.cost, 0.0);
  }
}

TEST(RrcTracker, HoldsWhenNoCycleIsFound) {
  const Polygon square = {{100, 100}, {200, 100}, {200, 200}, {100, 200}};
  const cv::Mat flat(480, 640, CV_8UC1, cv::Scalar(90));
  RrcTracker tracker;
  tracker.init(flat, square);
  const TrackResult result = tracker.track(flat);
  EXPECT_TRUE(result.held);
  EXPECT_EQ(result.boundary, square);
  EXPECT_EQ(result.num_detected, 0);
}

TEST(RrcTracker, RejectsBadOptions) {
  RrcTrackerOptions options;
  options.filter_distance = 0.0;
  EXPECT_THROW(RrcTracker{options}, std::invalid_argument);
  options = {};
  options.max_segments = 1;
  EXPECT_THROW(RrcTracker{options}, std::invalid_argument);
}

}  // namespace
}  // namespace scbt
