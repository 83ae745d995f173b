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
                         ::testing::Combine(::testing::Values(LineDetectorKind::kOpenCvEdLines,
                                                              LineDetectorKind::kEdLines,
                                                              LineDetectorKind::kLsd,
                                                              LineDetectorKind::kFastLineDetector),
                                            ::testing::Range(0u, 10u)),
                         [](const auto& info) {
                           std::string name = to_string(std::get<0>(info.param));
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name + "_" + std::to_string(std::get<1>(info.param));
                         });

TEST(LineDetector, BlankImageHasNoSegments) {
  const cv::Mat blank(120, 160, CV_8UC1, cv::Scalar(128));
  for (LineDetectorKind kind : {LineDetectorKind::kOpenCvEdLines, LineDetectorKind::kEdLines,
                                LineDetectorKind::kLsd, LineDetectorKind::kFastLineDetector}) {
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
  for (LineDetectorKind kind : {LineDetectorKind::kOpenCvEdLines, LineDetectorKind::kEdLines,
                                LineDetectorKind::kLsd, LineDetectorKind::kFastLineDetector}) {
    EXPECT_EQ(parse_line_detector_kind(to_string(kind)), kind);
  }
  EXPECT_EQ(to_string(LineDetectorKind::kEdLines), "edlines");
  EXPECT_EQ(to_string(LineDetectorKind::kOpenCvEdLines), "opencv-edlines");
  EXPECT_EQ(parse_line_detector_kind("scbt-edlines"), LineDetectorKind::kEdLines);
  EXPECT_EQ(LineDetectorOptions().kind, LineDetectorKind::kEdLines);  // ours is the default
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
      {[](LineDetectorOptions* o) { o->roi_padding = -1.0; }, "roi_padding"},
      {[=](LineDetectorOptions* o) { o->roi_padding = nan; }, "roi_padding"},
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

// The window grown around a random polygon lies in the frame, contains every polygon point within
// the frame grown by the margin, and is no larger than the grown bounding box needs.
TEST(DetectionRoi, CoversGrownBoundingBoxInsideFrame) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> coord(-50.0, 700.0), margin(0.0, 40.0);
  const cv::Size frame(640, 480);
  for (int trial = 0; trial < 200; ++trial) {
    Polygon polygon;
    for (int k = 0; k < 5; ++k) polygon.push_back({coord(rng), coord(rng)});
    const double m = margin(rng);
    const cv::Rect roi = detection_roi(polygon, m, frame);
    EXPECT_EQ(roi & cv::Rect(cv::Point(0, 0), frame), roi);
    for (const Point& p : polygon) {
      for (const Point& d : {Point(-m, -m), Point(m, m)}) {
        const Point q = p + d;
        const double x = std::clamp(q.x, 0.0, frame.width - 1.0);
        const double y = std::clamp(q.y, 0.0, frame.height - 1.0);
        EXPECT_TRUE(roi.contains(cv::Point(static_cast<int>(x), static_cast<int>(y))))
            << trial << ": " << x << "," << y << " outside " << roi;
      }
    }
    double x0 = 1e9, x1 = -1e9;
    for (const Point& p : polygon) x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
    EXPECT_LE(roi.width, std::ceil(x1 - x0 + 2 * m) + 3) << trial;
  }
}

TEST(EdLinesAutoMinLength, GrowsWithImageSize) {
  EXPECT_LT(edlines_auto_min_line_length({64, 48}), edlines_auto_min_line_length({640, 480}));
  EXPECT_GE(edlines_auto_min_line_length({640, 480}), 5);
  EXPECT_LE(edlines_auto_min_line_length({640, 480}), 8);
}

// Detecting in a window around a rendered rectangle finds, in frame coordinates, segments close
// to those found on the whole frame; with the window = the whole frame, exactly the same ones.
TEST(LineDetectorDetectIn, WindowMatchesWholeFrame) {
  for (unsigned seed = 0; seed < 12; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> x0(60, 300), y0(60, 200), w(60, 200), h(50, 150);
    const cv::Rect rect(x0(rng), y0(rng), w(rng), h(rng));
    cv::Mat image(480, 640, CV_8UC1, cv::Scalar(60));
    cv::rectangle(image, rect, cv::Scalar(200), cv::FILLED);
    cv::line(image, {0, 470}, {630, 10}, cv::Scalar(140), 3);  // a distractor crossing the frame
    for (LineDetectorKind kind : {LineDetectorKind::kOpenCvEdLines, LineDetectorKind::kEdLines,
                                  LineDetectorKind::kLsd, LineDetectorKind::kFastLineDetector}) {
      LineDetectorOptions options;
      options.kind = kind;
      std::unique_ptr<LineDetector> detector = make_line_detector(options);
      const std::vector<Segment> whole = detector->detect(image);
      const std::vector<Segment> same = detector->detect_in(image, cv::Point(0, 0), image.size());
      ASSERT_EQ(whole.size(), same.size()) << to_string(kind);
      for (size_t i = 0; i < whole.size(); ++i) {
        EXPECT_EQ(whole[i].a, same[i].a);
        EXPECT_EQ(whole[i].b, same[i].b);
      }
      const Polygon corners = {Point(rect.x, rect.y), Point(rect.br().x, rect.y),
                               Point(rect.br().x, rect.br().y), Point(rect.x, rect.br().y)};
      const cv::Rect roi = detection_roi(corners, 20.0, image.size());
      const std::vector<Segment> cropped = detector->detect_in(image(roi), roi.tl(), image.size());
      for (int side = 0; side < 4; ++side) {
        const Segment edge{corners[side], corners[(side + 1) % 4]};
        EXPECT_GT(covered_length(edge, cropped, 2.0), 0.95 * covered_length(edge, whole, 2.0) - 3.0)
            << to_string(kind) << " seed " << seed << " side " << side;
      }
      for (const Segment& s : cropped) {
        for (const Point& p : {s.a, s.b}) {
          EXPECT_TRUE(p.x >= roi.x - 0.5 && p.x <= roi.br().x + 0.5 && p.y >= roi.y - 0.5 &&
                      p.y <= roi.br().y + 0.5)
              << p << " outside " << roi;
        }
      }
    }
  }
}

}  // namespace
}  // namespace scbt
