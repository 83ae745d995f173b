// Every detector kind finds the sides of rendered rectangles; names and option checks.
#include "scbt/lines/line_detector.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <random>
#include <stdexcept>
#include <string>
#include <tuple>

namespace scbt {
namespace {

double point_segment_distance(const Point& p, const Point& a, const Point& b) {
  const Point d = b - a;
  const double t = std::clamp((p - a).dot(d) / d.dot(d), 0.0, 1.0);
  return cv::norm(p - (a + d * t));
}

// Length of the part of `side` covered by segments lying within `tolerance` of it (both
// endpoints near the side's line and near the side itself).
double covered_length(const Segment& side, const std::vector<Segment>& segments, double tolerance) {
  const Point dir = (side.b - side.a) * (1.0 / side.length());
  double best = 0.0;
  for (const Segment& s : segments) {
    if (point_segment_distance(s.a, side.a, side.b) > tolerance ||
        point_segment_distance(s.b, side.a, side.b) > tolerance) {
      continue;
    }
    const double t0 = (s.a - side.a).dot(dir), t1 = (s.b - side.a).dot(dir);
    best = std::max(best, std::abs(t1 - t0));
  }
  return best;
}

class LineDetectorFindsRectangle
    : public ::testing::TestWithParam<std::tuple<LineDetectorKind, unsigned>> {};

TEST_P(LineDetectorFindsRectangle, EachSideMatchedBySegment) {
  const auto [kind, seed] = GetParam();
  std::mt19937 rng(seed + 100u * static_cast<unsigned>(kind));
  std::uniform_int_distribution<int> x0(20, 120), y0(20, 90), w(60, 160), h(50, 110), dark(0, 80),
      bright(150, 255);
  const int left = x0(rng), top = y0(rng), width = w(rng), height = h(rng);
  // Dark object on bright ground or the reverse.
  int background = dark(rng), foreground = bright(rng);
  if (seed % 2 == 1) std::swap(background, foreground);
  cv::Mat image(240, 320, CV_8UC1, cv::Scalar(background));
  cv::rectangle(image, cv::Rect(left, top, width, height), cv::Scalar(foreground), cv::FILLED);

  LineDetectorOptions options;
  options.kind = kind;
  const std::vector<Segment> segments = make_line_detector(options)->detect(image);
  ASSERT_FALSE(segments.empty());
  for (const Segment& s : segments) {  // all inside the image
    for (const Point& p : {s.a, s.b}) {
      EXPECT_GE(p.x, -1.0);
      EXPECT_LE(p.x, 321.0);
      EXPECT_GE(p.y, -1.0);
      EXPECT_LE(p.y, 241.0);
    }
  }
  // The filled pixels span [left, left + width) x [top, top + height); the edge lies between
  // pixel centres, at +-0.5 px of the outermost filled ones.
  const double l = left - 0.5, r = left + width - 0.5, t = top - 0.5, b = top + height - 0.5;
  const Segment sides[4] = {{{l, t}, {r, t}}, {{r, t}, {r, b}}, {{r, b}, {l, b}}, {{l, b}, {l, t}}};
  for (const Segment& side : sides) {
    const double covered = covered_length(side, segments, 2.0);
    EXPECT_GT(covered, 0.8 * side.length())
        << to_string(kind) << ": side (" << side.a << ")-(" << side.b << ") of length "
        << side.length() << " covered " << covered;
  }
}

INSTANTIATE_TEST_SUITE_P(Kinds, LineDetectorFindsRectangle,
                         ::testing::Combine(::testing::Values(LineDetectorKind::kEdLines,
                                                              LineDetectorKind::kLsd,
                                                              LineDetectorKind::kFastLineDetector),
                                            ::testing::Range(0u, 10u)),
                         [](const auto& info) {
                           return to_string(std::get<0>(info.param)) + "_" +
                                  std::to_string(std::get<1>(info.param));
                         });

TEST(LineDetector, BlankImageHasNoSegments) {
  const cv::Mat blank(120, 160, CV_8UC1, cv::Scalar(128));
  for (LineDetectorKind kind :
       {LineDetectorKind::kEdLines, LineDetectorKind::kLsd, LineDetectorKind::kFastLineDetector}) {
    LineDetectorOptions options;
    options.kind = kind;
    EXPECT_TRUE(make_line_detector(options)->detect(blank).empty()) << to_string(kind);
  }
}

TEST(LineDetector, ConvenienceAcceptsColourAndMinLengthFilters) {
  cv::Mat image(200, 200, CV_8UC3, cv::Scalar(20, 20, 20));
  cv::rectangle(image, cv::Rect(50, 50, 100, 30), cv::Scalar(230, 230, 230), cv::FILLED);
  LineDetectorOptions options;
  options.kind = LineDetectorKind::kLsd;
  const std::vector<Segment> all = detect_line_segments(image, options);
  ASSERT_FALSE(all.empty());
  options.min_line_length = 60.0;
  const std::vector<Segment> long_only = detect_line_segments(image, options);
  EXPECT_LT(long_only.size(), all.size());  // the 30 px sides are gone
  EXPECT_FALSE(long_only.empty());
  for (const Segment& s : long_only) EXPECT_GE(s.length(), 60.0);
}

TEST(LineDetectorKindNames, RoundTripAndUnknown) {
  for (LineDetectorKind kind :
       {LineDetectorKind::kEdLines, LineDetectorKind::kLsd, LineDetectorKind::kFastLineDetector}) {
    EXPECT_EQ(parse_line_detector_kind(to_string(kind)), kind);
  }
  EXPECT_EQ(to_string(LineDetectorKind::kEdLines), "edlines");
  EXPECT_EQ(to_string(LineDetectorKind::kLsd), "lsd");
  EXPECT_EQ(to_string(LineDetectorKind::kFastLineDetector), "fld");
  for (const std::string bad : {"", "EDLINES", "hough", "lsd "}) {
    try {
      parse_line_detector_kind(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("'" + bad + "'"), std::string::npos) << e.what();
    }
  }
}

TEST(LineDetectorOptions, CheckRejectsBadValues) {
  EXPECT_NO_THROW(LineDetectorOptions().check());
  struct Case {
    std::function<void(LineDetectorOptions*)> change;
    std::string name;
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Case> cases = {
      {[](LineDetectorOptions* o) { o->gradient_threshold = 0; }, "gradient_threshold"},
      {[](LineDetectorOptions* o) { o->gradient_threshold = 256; }, "gradient_threshold"},
      {[](LineDetectorOptions* o) { o->anchor_threshold = -1; }, "anchor_threshold"},
      {[](LineDetectorOptions* o) { o->anchor_threshold = 256; }, "anchor_threshold"},
      {[](LineDetectorOptions* o) { o->scan_interval = 0; }, "scan_interval"},
      {[](LineDetectorOptions* o) { o->sigma = 0.0; }, "sigma"},
      {[](LineDetectorOptions* o) { o->sigma = 11.0; }, "sigma"},
      {[=](LineDetectorOptions* o) { o->sigma = nan; }, "sigma"},
      {[](LineDetectorOptions* o) { o->line_fit_error = 0.0; }, "line_fit_error"},
      {[](LineDetectorOptions* o) { o->line_fit_error = 101.0; }, "line_fit_error"},
      {[=](LineDetectorOptions* o) { o->min_line_length = nan; }, "min_line_length"},
      {[](LineDetectorOptions* o) { o->min_line_length = 1e5; }, "min_line_length"},
  };
  for (const Case& c : cases) {
    LineDetectorOptions options;
    c.change(&options);
    try {
      options.check();
      ADD_FAILURE() << "accepted a bad " << c.name;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(c.name), std::string::npos) << e.what();
    }
    EXPECT_THROW(make_line_detector(options), std::invalid_argument) << c.name;
  }
}

}  // namespace
}  // namespace scbt
