#include "scbt/lines/boundary_samples.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <opencv2/core.hpp>
#include <random>

namespace scbt {
namespace {

cv::Mat noise_image(int rows, int cols, unsigned seed) {
  cv::Mat image(rows, cols, CV_8UC1);
  cv::RNG rng(seed);
  rng.fill(image, cv::RNG::UNIFORM, 0, 256);
  return image;
}

// The interpolation written out with integer levels and differences, as the measurements were
// calibrated with: the sampler must give the same doubles.
double written_out(const cv::Mat& image, double x, double y) {
  const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
  const double fx = x - x0, fy = y - y0;
  const std::uint8_t* r0 = image.ptr<std::uint8_t>(y0);
  const std::uint8_t* r1 = image.ptr<std::uint8_t>(y0 + 1);
  const double top = r0[x0] + fx * (r0[x0 + 1] - r0[x0]);
  const double bottom = r1[x0] + fx * (r1[x0 + 1] - r1[x0]);
  return top + fy * (bottom - top);
}

TEST(GreySampler, InterpolatesBetweenTheFourNearestPixels) {
  const cv::Mat image = (cv::Mat_<std::uint8_t>(2, 3) << 0, 100, 200, 50, 150, 250);
  const GreySampler sampler(image);
  EXPECT_EQ(sampler.inside(0.0, 0.0), 0.0);
  EXPECT_EQ(sampler.inside(1.0, 0.0), 100.0);
  EXPECT_EQ(sampler.inside(0.5, 0.0), 50.0);
  EXPECT_EQ(sampler.inside(0.5, 0.5), 75.0);
  EXPECT_EQ(sampler.inside(1.25, 0.5), 150.0);
  // Beyond the last column and row the clamp holds the sample on the border.
  EXPECT_NEAR(sampler.clamped(7.0, -3.0), 200.0, 0.2);
  EXPECT_NEAR(sampler.clamped(-1.0, 9.0), 50.0, 0.1);
}

TEST(GreySampler, InsideReadsWhatTheClampedSampleReadsWhereTheClampChangesNothing) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    std::mt19937 random(seed);
    const int rows = 2 + static_cast<int>(random() % 60),
              cols = 2 + static_cast<int>(random() % 60);
    // A view into a larger image: rows not contiguous.
    const cv::Mat whole = noise_image(rows + 4, cols + 7, seed);
    const cv::Mat image = whole(cv::Rect(3, 2, cols, rows));
    const GreySampler sampler(image);
    std::uniform_real_distribution<double> x(0.0, cols - 1.001), y(0.0, rows - 1.001);
    for (int i = 0; i < 200; ++i) {
      const double px = x(random), py = y(random);
      EXPECT_EQ(sampler.inside(px, py), sampler.clamped(px, py)) << px << " " << py;
      EXPECT_EQ(sampler.inside(px, py), bilinear_grey(image, px, py)) << px << " " << py;
      EXPECT_EQ(sampler.inside(px, py), written_out(image, px, py)) << px << " " << py;
    }
  }
}

TEST(GreySampler, HoldsADiscOnlyWhenTheClampLeavesAllOfItAlone) {
  const cv::Mat image = noise_image(40, 60, 3);
  const GreySampler sampler(image);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> x(-5.0, 65.0), y(-5.0, 45.0), radius(0.0, 12.0);
  int held = 0;
  for (int i = 0; i < 2000; ++i) {
    const Point p(x(random), y(random));
    const double r = radius(random);
    if (!sampler.holds_disc(p, r)) continue;
    ++held;
    for (int k = 0; k < 16; ++k) {
      const double angle = 2.0 * CV_PI * k / 16;
      const Point q = p + r * Point(std::cos(angle), std::sin(angle));
      EXPECT_EQ(sampler.inside(q.x, q.y), sampler.clamped(q.x, q.y));
    }
  }
  EXPECT_GT(held, 100);
  EXPECT_TRUE(sampler.holds_disc({30.0, 20.0}, 8.0));
  EXPECT_FALSE(sampler.holds_disc({7.9, 20.0}, 8.0));
  EXPECT_FALSE(sampler.holds_disc({30.0, 31.0}, 8.0));  // 31 + 8 > 40 - 1.001
}

}  // namespace
}  // namespace scbt
