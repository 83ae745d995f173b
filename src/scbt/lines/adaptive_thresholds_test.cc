#include "scbt/lines/adaptive_thresholds.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

namespace scbt {
namespace {

// A dark square on a lighter ground with the given step height, optionally blurred and noisy.
cv::Mat scene(double step, double blur_sigma, double noise_sigma) {
  cv::Mat m(200, 200, CV_32F, cv::Scalar(60.0 + step));
  cv::rectangle(m, cv::Rect(50, 50, 100, 100), cv::Scalar(60.0), cv::FILLED);
  if (blur_sigma > 0) cv::GaussianBlur(m, m, cv::Size(), blur_sigma);
  if (noise_sigma > 0) {
    cv::Mat noise(m.size(), CV_32F);
    cv::RNG rng(3);
    rng.fill(noise, cv::RNG::NORMAL, 0.0, noise_sigma);
    m += noise;
  }
  cv::Mat out;
  m.convertTo(out, CV_8U);
  return out;
}

const Polygon kSquare = {{50, 50}, {149.5, 50}, {149.5, 149.5}, {50, 149.5}};

TEST(AdaptiveThresholds, NoiseEstimateFollowsTheNoise) {
  EXPECT_LT(estimate_noise_sigma(scene(80, 0, 0)), 1.0);
  for (double sigma : {3.0, 8.0, 15.0}) {
    EXPECT_NEAR(estimate_noise_sigma(scene(80, 0, sigma)), sigma, 0.15 * sigma + 0.5) << sigma;
  }
}

TEST(AdaptiveThresholds, BoundaryStrengthScalesWithContrastAndFallsWithBlur) {
  const double strong = boundary_edge_strength(scene(80, 0, 0), {0, 0}, kSquare, 48, 6);
  const double weak = boundary_edge_strength(scene(24, 0, 0), {0, 0}, kSquare, 48, 6);
  const double blurred = boundary_edge_strength(scene(80, 3, 0), {0, 0}, kSquare, 48, 6);
  EXPECT_NEAR(weak / strong, 24.0 / 80.0, 0.03);
  EXPECT_LT(blurred, 0.5 * strong);
  // A boundary drawn 4 px off is still found within the reach.
  Polygon off = kSquare;
  for (Point& p : off) p += Point(4, 0);
  EXPECT_NEAR(boundary_edge_strength(scene(80, 0, 0), {0, 0}, off, 48, 6), strong, 0.1 * strong);
  // The window's offset is honoured.
  const cv::Mat whole = scene(80, 0, 0);
  EXPECT_NEAR(boundary_edge_strength(whole(cv::Rect(20, 10, 170, 180)), {20, 10}, kSquare, 48, 6),
              strong, 1e-9);
}

TEST(AdaptiveThresholds, KeepsThePublishedValuesOnAClearImage) {
  AdaptiveThresholdOptions options;
  options.enabled = true;
  const EdgeThresholds t = adapt_edge_thresholds(scene(80, 0, 1), {0, 0}, kSquare, 36, 8, options);
  EXPECT_EQ(t.gradient, 36);
  EXPECT_EQ(t.anchor, 8);
}

TEST(AdaptiveThresholds, LowersThemForADimOrBlurredBoundaryButNotBelowNoise) {
  AdaptiveThresholdOptions options;
  options.enabled = true;
  const EdgeThresholds dim =
      adapt_edge_thresholds(scene(12, 0, 0), {0, 0}, kSquare, 36, 8, options);
  EXPECT_LT(dim.gradient, 36);
  EXPECT_LE(dim.gradient, 0.5 * dim.boundary_gradient + 1);
  EXPECT_LT(dim.anchor, 8);
  const EdgeThresholds blurred =
      adapt_edge_thresholds(scene(40, 3, 0), {0, 0}, kSquare, 36, 8, options);
  EXPECT_LT(blurred.gradient, 36);
  // Noise keeps a dim boundary's threshold from dropping as far (but never raises it above 36).
  const EdgeThresholds noisy =
      adapt_edge_thresholds(scene(12, 0, 15), {0, 0}, kSquare, 36, 8, options);
  EXPECT_GT(noisy.gradient, dim.gradient);
  EXPECT_LE(noisy.gradient, 36);
  EXPECT_NEAR(noisy.noise_sigma, 15.0, 3.0);
  AdaptiveThresholdOptions off;
  off.enabled = false;
  const EdgeThresholds fixed = adapt_edge_thresholds(scene(24, 0, 0), {0, 0}, kSquare, 36, 8, off);
  EXPECT_EQ(fixed.gradient, 36);
  EXPECT_EQ(fixed.anchor, 8);
}

TEST(AdaptiveThresholds, SmoothsANoisyWindowOnly) {
  AdaptiveThresholdOptions options;
  options.enabled = true;
  options.smooth_noise = true;
  cv::Mat smoothed;
  EdgeThresholds t;
  const cv::Mat clean = scene(80, 0, 1);
  const cv::Mat& clean_out = adapt_to_frame(clean, {0, 0}, kSquare, 36, 8, options, &smoothed, &t);
  EXPECT_EQ(clean_out.data, clean.data);  // nothing to smooth: the input itself
  EXPECT_EQ(t.pre_smoothing, 0.0);
  const cv::Mat noisy = scene(80, 0, 15);
  const cv::Mat& noisy_out = adapt_to_frame(noisy, {0, 0}, kSquare, 36, 8, options, &smoothed, &t);
  EXPECT_EQ(noisy_out.data, smoothed.data);
  // sigma_n / (2 sqrt(pi) 2) for sigma_n about 15: about 2.1 px.
  EXPECT_NEAR(t.pre_smoothing, 15.0 / (4.0 * std::sqrt(CV_PI)), 0.4);
  EXPECT_LT(estimate_noise_sigma(noisy_out), 0.35 * t.noise_sigma);
  // The boundary's strength is read on the smoothed window: still well above the noise floor.
  EXPECT_GT(t.boundary_gradient, 2.0 * t.gradient);
  options.smoothed_noise = 0;
  EXPECT_THROW(options.check(), std::invalid_argument);
}

TEST(AdaptiveThresholds, TakesANoiseAlreadyMeasured) {
  AdaptiveThresholdOptions options;
  options.enabled = true;
  options.smooth_noise = false;
  const cv::Mat noisy = scene(24, 2, 6);
  EdgeThresholds estimated, given, louder;
  adapt_to_frame(noisy, {0, 0}, kSquare, 36, 8, options, nullptr, &estimated);
  adapt_to_frame(noisy, {0, 0}, kSquare, 36, 8, options, nullptr, &given, estimated.noise_sigma);
  EXPECT_EQ(given.noise_sigma, estimated.noise_sigma);
  EXPECT_EQ(given.gradient, estimated.gradient);
  EXPECT_EQ(given.anchor, estimated.anchor);
  // A louder camera than this window shows raises the noise floor the thresholds stop at.
  adapt_to_frame(noisy, {0, 0}, kSquare, 36, 8, options, nullptr, &louder,
                 3.0 * estimated.noise_sigma);
  EXPECT_EQ(louder.noise_sigma, 3.0 * estimated.noise_sigma);
  EXPECT_GT(louder.gradient, estimated.gradient);
}

TEST(AdaptiveThresholds, RejectsBadOptions) {
  AdaptiveThresholdOptions o;
  o.boundary_fraction = 0;
  EXPECT_THROW(o.check(), std::invalid_argument);
  o = {};
  o.boundary_samples = 2;
  EXPECT_THROW(o.check(), std::invalid_argument);
  o = {};
  o.search_reach = 0.5;
  EXPECT_THROW(o.check(), std::invalid_argument);
  EXPECT_NO_THROW(AdaptiveThresholdOptions().check());
}

}  // namespace
}  // namespace scbt
