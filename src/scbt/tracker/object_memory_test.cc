#include "scbt/tracker/object_memory.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

namespace scbt {
namespace {

Polygon ellipse_outline(Point centre, double rx, double ry, int n = 40) {
  Polygon p;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * CV_PI * i / n;
    p.emplace_back(centre.x + rx * std::cos(t), centre.y + ry * std::sin(t));
  }
  return p;
}

// A bright ellipse on a darker, noisy background.
cv::Mat render(const Polygon& outline, cv::RNG* rng) {
  cv::Mat frame(480, 640, CV_8U, cv::Scalar(70));
  std::vector<cv::Point> pts;
  for (const Point& p : outline) pts.emplace_back(cvRound(p.x * 16), cvRound(p.y * 16));
  cv::fillPoly(frame, std::vector<std::vector<cv::Point>>{pts}, cv::Scalar(170), cv::LINE_AA, 4);
  cv::Mat noise(frame.size(), CV_8S);
  rng->fill(noise, cv::RNG::NORMAL, 0, 3);
  cv::Mat out;
  cv::add(frame, noise, out, cv::noArray(), CV_8U);
  return out;
}

double mean_distance(const Polygon& a, const Polygon& b) {
  double sum = 0.0;
  for (const Point& p : a) sum += distance_to_boundary(p, b);
  return sum / a.size();
}

TEST(ResampleOutline, EvenlySpacedAlongTheLength) {
  const Polygon square{{0, 0}, {100, 0}, {100, 100}, {0, 100}};
  const Polygon r = resample_outline(square, 8);
  ASSERT_EQ(r.size(), 8u);
  for (size_t i = 0; i < r.size(); ++i) {
    const Point d = r[(i + 1) % r.size()] - r[i];
    EXPECT_NEAR(std::abs(d.x) + std::abs(d.y), 50.0, 1e-9);
  }
}

// Moved by a few pixels in any direction, the fitted outline follows, fully visible.
TEST(ObjectMemory, FollowsAShiftOfTheObject) {
  cv::RNG rng(3);
  const Polygon start = ellipse_outline({320, 240}, 90, 60);
  for (const Point shift : {Point(4, -3), Point(-6, 2), Point(0, 7), Point(-5, -5)}) {
    ObjectMemory memory;
    memory.remember(start, render(start, &rng), {0, 0});
    Polygon moved = start;
    for (Point& p : moved) p += shift;
    const MemoryFit fit = memory.fit(render(moved, &rng), {0, 0});
    ASSERT_TRUE(fit.valid);
    EXPECT_LT(mean_distance(fit.outline, moved), 0.8) << shift;
    EXPECT_GT(fit.visible, 0.9) << shift;
  }
}

// A bar of another grey level over part of the outline: the outline is still placed by the
// visible part, and the visible fraction says how much of it was seen.
TEST(ObjectMemory, PlacesAPartlyHiddenObjectAndSaysHowMuchIsVisible) {
  cv::RNG rng(5);
  const Polygon start = ellipse_outline({320, 240}, 90, 60);
  for (int bar_x : {220, 300, 370}) {
    ObjectMemory memory;
    memory.remember(start, render(start, &rng), {0, 0});
    Polygon moved = start;
    for (Point& p : moved) p += Point(3, 2);
    cv::Mat frame = render(moved, &rng);
    cv::rectangle(frame, cv::Rect(bar_x, 0, 50, 480), cv::Scalar(120), cv::FILLED);
    const MemoryFit fit = memory.fit(frame, {0, 0});
    ASSERT_TRUE(fit.valid) << bar_x;
    EXPECT_LT(mean_distance(fit.outline, moved), 1.0) << bar_x;
    EXPECT_GT(fit.visible, 0.45) << bar_x;
    EXPECT_LT(fit.visible, 0.9) << bar_x;
  }
}

// The mismatch of a cycle that takes in a neighbouring region along part of the outline.
TEST(ObjectMemory, MismatchCountsTheDepartingPart) {
  const ObjectMemory memory;
  const Polygon a{{0, 0}, {100, 0}, {100, 100}, {0, 100}};
  EXPECT_EQ(memory.mismatch(a, a, 3.0), 0.0);
  const Polygon leaked{{0, 0}, {160, 0}, {160, 100}, {0, 100}};
  EXPECT_GT(memory.mismatch(leaked, a, 3.0), 0.25);
  EXPECT_GT(memory.mismatch(a, leaked, 3.0), 0.25);
}

}  // namespace
}  // namespace scbt
