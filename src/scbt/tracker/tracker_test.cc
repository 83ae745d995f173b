// Tracker contract: option validation, init/track preconditions, holding, and following a
// rendered polygon (the end-to-end synthetic clips are in tracker_synthetic_test.cc).
#include "scbt/tracker/tracker.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

#include "scbt/tracker/frame_checks.h"

namespace scbt {
namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

void expect_invalid(const std::function<void(TrackerOptions*)>& change, const std::string& name) {
  TrackerOptions options;
  change(&options);
  try {
    options.check();
    ADD_FAILURE() << "check() accepted a bad " << name;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
  }
  EXPECT_THROW(Tracker{options}, std::invalid_argument) << name;
}

TEST(TrackerOptions, DefaultsAreValid) {
  EXPECT_NO_THROW(TrackerOptions().check());
  EXPECT_NO_THROW(Tracker{});
}

TEST(TrackerOptions, CheckRejectsEachBadValue) {
  expect_invalid([](TrackerOptions* o) { o->filter_distance = 0.0; }, "filter_distance");
  expect_invalid([](TrackerOptions* o) { o->filter_distance = -3.0; }, "filter_distance");
  expect_invalid([](TrackerOptions* o) { o->filter_distance = kNaN; }, "filter_distance");
  expect_invalid([](TrackerOptions* o) { o->min_area_similarity = -0.1; }, "min_area_similarity");
  expect_invalid([](TrackerOptions* o) { o->min_area_similarity = 1.0; }, "min_area_similarity");
  expect_invalid([](TrackerOptions* o) { o->min_area_similarity = kNaN; }, "min_area_similarity");
  expect_invalid([](TrackerOptions* o) { o->cost_tolerance = -0.01; }, "cost_tolerance");
  expect_invalid([](TrackerOptions* o) { o->cost_tolerance = kNaN; }, "cost_tolerance");
  expect_invalid([](TrackerOptions* o) { o->bdsp.seed_stride = 0; }, "seed_stride");
  expect_invalid([](TrackerOptions* o) { o->bdsp.seed_stride = -2; }, "seed_stride");
  expect_invalid([](TrackerOptions* o) { o->detector.gradient_threshold = 0; },
                 "gradient_threshold");
  expect_invalid([](TrackerOptions* o) { o->detector.anchor_threshold = -1; }, "anchor_threshold");
  expect_invalid([](TrackerOptions* o) { o->detector.scan_interval = 0; }, "scan_interval");
  expect_invalid([](TrackerOptions* o) { o->detector.sigma = 0.0; }, "sigma");
  expect_invalid([](TrackerOptions* o) { o->detector.line_fit_error = 0.0; }, "line_fit_error");
  // Edge values that are valid.
  TrackerOptions options;
  options.min_area_similarity = 0.0;
  options.cost_tolerance = 0.0;
  options.bdsp.seed_stride = 1;
  EXPECT_NO_THROW(options.check());
}

// A filled irregular pentagon, bright on dark, at `offset`.
Polygon pentagon(Point offset) {
  Polygon p{{100, 70}, {190, 80}, {215, 150}, {150, 190}, {85, 160}};
  for (Point& v : p) v += offset;
  return p;
}

cv::Mat render(const Polygon& polygon, int type = CV_8UC1, cv::Size size = {320, 240}) {
  cv::Mat image(size, type, cv::Scalar::all(40));
  std::vector<cv::Point> pts;
  for (const Point& v : polygon) pts.emplace_back(cvRound(v.x), cvRound(v.y));
  cv::fillPoly(image, std::vector<std::vector<cv::Point>>{pts}, cv::Scalar::all(210), cv::LINE_8);
  return image;
}

TEST(Tracker, InitRejectsBadFramesAndPolygons) {
  const Polygon good = pentagon({0, 0});
  const cv::Mat frame = render(good);
  Tracker tracker;
  EXPECT_FALSE(tracker.initialized());
  EXPECT_THROW(tracker.init(cv::Mat(), good), std::invalid_argument);
  EXPECT_THROW(tracker.init(cv::Mat(240, 320, CV_16UC1, cv::Scalar(0)), good),
               std::invalid_argument);
  EXPECT_THROW(tracker.init(cv::Mat(240, 320, CV_32FC1, cv::Scalar(0)), good),
               std::invalid_argument);
  EXPECT_THROW(tracker.init(cv::Mat(240, 320, CV_8UC2, cv::Scalar(0, 0)), good),
               std::invalid_argument);
  EXPECT_THROW(tracker.init(frame, {{10, 10}, {20, 20}}), std::invalid_argument);
  EXPECT_THROW(tracker.init(frame, {{10, 10}, {100, 100}, {100, 10}, {10, 100}}),
               std::invalid_argument);  // bow-tie
  EXPECT_THROW(tracker.init(frame, {{10, 10}, {20, 10}, {kNaN, 20}}), std::invalid_argument);
  // Outside the frame, on each side.
  EXPECT_THROW(tracker.init(frame, pentagon({200, 0})), std::invalid_argument);
  EXPECT_THROW(tracker.init(frame, pentagon({0, 100})), std::invalid_argument);
  EXPECT_THROW(tracker.init(frame, pentagon({-90, 0})), std::invalid_argument);
  EXPECT_THROW(tracker.init(frame, pentagon({0, -75})), std::invalid_argument);
  EXPECT_FALSE(tracker.initialized());

  tracker.init(frame, good);
  EXPECT_TRUE(tracker.initialized());
  EXPECT_EQ(tracker.boundary(), good);
  // Touching the frame border is allowed.
  EXPECT_NO_THROW(tracker.init(frame, {{0, 0}, {320, 0}, {320, 240}, {0, 240}}));
}

TEST(Tracker, TrackBeforeInitIsALogicError) {
  Tracker tracker;
  EXPECT_THROW(tracker.track(render(pentagon({0, 0}))), std::logic_error);
}

TEST(Tracker, BlankFrameIsHeld) {
  const Polygon polygon = pentagon({0, 0});
  Tracker tracker;
  tracker.init(render(polygon), polygon);
  const TrackResult result = tracker.track(cv::Mat(240, 320, CV_8UC1, cv::Scalar(40)));
  EXPECT_TRUE(result.held);
  EXPECT_EQ(result.boundary, polygon);
  EXPECT_EQ(tracker.boundary(), polygon);
  EXPECT_EQ(result.num_detected, 0);
  EXPECT_EQ(result.num_candidates, 0);
  EXPECT_EQ(result.step, SearchStep::kNone);
}

TEST(Tracker, FrameSizeChangeThrows) {
  const Polygon polygon = pentagon({0, 0});
  Tracker tracker;
  tracker.init(render(polygon), polygon);
  EXPECT_THROW(tracker.track(render(polygon, CV_8UC1, {330, 240})), std::invalid_argument);
  EXPECT_THROW(tracker.track(cv::Mat(240, 320, CV_16UC1, cv::Scalar(0))), std::invalid_argument);
}

double mean_vertex_distance(const Polygon& from, const Polygon& to) {
  double sum = 0.0;
  for (const Point& p : from) sum += distance_to_boundary(p, to);
  return sum / static_cast<double>(from.size());
}

class TrackerFollows : public ::testing::TestWithParam<int> {};

TEST_P(TrackerFollows, ShiftedRenderedPolygon) {
  const int type = GetParam();
  Polygon truth = pentagon({0, 0});
  Tracker tracker;
  tracker.set_keep_debug(true);
  tracker.init(render(truth, type), truth);
  const Point step(4.0, 3.0);
  for (int frame = 1; frame <= 4; ++frame) {
    SCOPED_TRACE("frame " + std::to_string(frame));
    const Polygon before = tracker.boundary();
    for (Point& v : truth) v += step;
    const TrackResult result = tracker.track(render(truth, type));
    ASSERT_FALSE(result.held);
    EXPECT_EQ(result.step, SearchStep::kPredicted);
    EXPECT_GT(result.num_detected, 0);
    EXPECT_GT(result.num_candidates, 0);
    EXPECT_GT(result.area_similarity, 0.9);
    EXPECT_EQ(result.boundary, tracker.boundary());
    // Every tracked vertex lies on the true outline and the outline's corners are covered.
    EXPECT_LT(mean_vertex_distance(result.boundary, truth), 1.5);
    EXPECT_LT(mean_vertex_distance(truth, result.boundary), 3.0);
    const Point moved = centroid(result.boundary) - centroid(before);
    EXPECT_NEAR(moved.x, step.x, 1.5);
    EXPECT_NEAR(moved.y, step.y, 1.5);
    EXPECT_NEAR(area(result.boundary), area(truth), 0.05 * area(truth));
    EXPECT_EQ(static_cast<int>(tracker.debug().detected.size()), result.num_detected);
    EXPECT_EQ(tracker.debug().graph.num_vertices(), result.num_vertices);
  }
}

INSTANTIATE_TEST_SUITE_P(FrameTypes, TrackerFollows, ::testing::Values(CV_8UC1, CV_8UC3, CV_8UC4));

TEST(SearchStep, EveryStepHasItsName) {
  EXPECT_STREQ(step_name(SearchStep::kNone), "none");
  EXPECT_STREQ(step_name(SearchStep::kPredicted), "predicted");
  EXPECT_STREQ(step_name(SearchStep::kUnmoved), "unmoved");
  EXPECT_STREQ(step_name(SearchStep::kGrowth), "growth");
  EXPECT_STREQ(step_name(SearchStep::kSmaller), "smaller");
  EXPECT_STREQ(step_name(SearchStep::kImageMotion), "image motion");
  EXPECT_STREQ(step_name(SearchStep::kInPlace), "in place");
  EXPECT_STREQ(step_name(SearchStep::kWholeFrame), "whole frame");
}

TEST(ToGray, ChannelsAndDepths) {
  cv::Mat gray;
  const cv::Mat one(10, 12, CV_8UC1, cv::Scalar(7));
  to_gray(one, &gray);
  EXPECT_NE(gray.data, one.data);  // a copy (frame_ownership_test.cc)
  EXPECT_EQ(gray.at<uchar>(3, 4), 7);
  to_gray(cv::Mat(10, 12, CV_8UC3, cv::Scalar(100, 100, 100)), &gray);
  EXPECT_EQ(gray.type(), CV_8UC1);
  EXPECT_EQ(gray.at<uchar>(3, 4), 100);
  to_gray(cv::Mat(10, 12, CV_8UC4, cv::Scalar(50, 50, 50, 255)), &gray);
  EXPECT_EQ(gray.type(), CV_8UC1);
  EXPECT_EQ(gray.at<uchar>(0, 0), 50);
  EXPECT_THROW(to_gray(cv::Mat(), &gray), std::invalid_argument);
  EXPECT_THROW(to_gray(cv::Mat(4, 4, CV_8UC2, cv::Scalar(0, 0)), &gray), std::invalid_argument);
  EXPECT_THROW(to_gray(cv::Mat(4, 4, CV_16UC3, cv::Scalar(0, 0, 0)), &gray), std::invalid_argument);
}

}  // namespace
}  // namespace scbt
