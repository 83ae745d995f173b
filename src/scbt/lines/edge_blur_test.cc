#include "scbt/lines/edge_blur.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace scbt {
namespace {

// A 240x240 grey frame holding a square of side 120 centred in it, 60 inside and 190 outside,
// drawn 8x larger and averaged down (a step spread over about a pixel, as a camera's), then
// Gaussian-blurred by `blur` px (none for 0).
cv::Mat square_frame(double blur) {
  cv::Mat large(240 * 8, 240 * 8, CV_8U, cv::Scalar(190));
  cv::rectangle(large, cv::Rect(60 * 8, 60 * 8, 120 * 8, 120 * 8), cv::Scalar(60), cv::FILLED);
  cv::Mat frame;
  cv::resize(large, frame, cv::Size(240, 240), 0.0, 0.0, cv::INTER_AREA);
  if (blur > 0.0) cv::GaussianBlur(frame, frame, cv::Size(0, 0), blur);
  return frame;
}

const Polygon kSquare = {{60, 60}, {180, 60}, {180, 180}, {60, 180}};

TEST(EstimateEdgeBlur, ReadsTheBlurAddedToAStep) {
  const EdgeBlurOptions options;
  const double sharp = estimate_edge_blur(square_frame(0.0), {0, 0}, kSquare, 18.0, options);
  ASSERT_GT(sharp, 0.0);
  EXPECT_LT(sharp, 1.5);  // a focused camera's spread, plus the central differences' own
  double previous = sharp;
  for (const double blur : {1.5, 2.5, 3.5}) {
    const double sigma = estimate_edge_blur(square_frame(blur), {0, 0}, kSquare, 18.0, options);
    // Variances add: the blur is what the spread gained (read a little short for a wide one,
    // whose tails leave the profile's 7 px).
    EXPECT_NEAR(std::sqrt(sigma * sigma - sharp * sharp), blur, 0.15 * blur) << "blur " << blur;
    EXPECT_GT(sigma, previous);
    previous = sigma;
  }
}

TEST(EstimateEdgeBlur, ReadsTheWindowInFrameCoordinates) {
  const EdgeBlurOptions options;
  const cv::Mat frame = square_frame(2.5);
  const cv::Rect window(30, 40, 190, 180);
  EXPECT_DOUBLE_EQ(estimate_edge_blur(frame(window), window.tl(), kSquare, 18.0, options),
                   estimate_edge_blur(frame, {0, 0}, kSquare, 18.0, options));
}

TEST(EstimateEdgeBlur, UnknownWithoutAClearStepOrOutsideTheWindow) {
  const EdgeBlurOptions options;
  const cv::Mat flat(240, 240, CV_8U, cv::Scalar(128));
  EXPECT_EQ(estimate_edge_blur(flat, {0, 0}, kSquare, 18.0, options), -1.0);
  // The step (130 levels) is below the one asked for.
  EXPECT_EQ(estimate_edge_blur(square_frame(0.0), {0, 0}, kSquare, 140.0, options), -1.0);
  // A boundary 30 px inside the square crosses no edge.
  const Polygon inner = {{90, 90}, {150, 90}, {150, 150}, {90, 150}};
  EXPECT_EQ(estimate_edge_blur(square_frame(0.0), {0, 0}, inner, 18.0, options), -1.0);
  // A boundary the window does not hold.
  EXPECT_EQ(
      estimate_edge_blur(square_frame(0.0)(cv::Rect(0, 0, 50, 50)), {0, 0}, kSquare, 18.0, options),
      -1.0);
  EXPECT_EQ(estimate_edge_blur(cv::Mat(), {0, 0}, kSquare, 18.0, options), -1.0);
}

TEST(EdgeBlurGain, OneForASharpCameraFallingWithTheSpread) {
  const EdgeBlurOptions options;
  EXPECT_EQ(edge_blur_gain(-1.0, 1.0, options), 1.0);  // unknown
  EXPECT_EQ(edge_blur_gain(1.3, 1.0, options), 1.0);
  EXPECT_EQ(edge_blur_gain(1.9, 1.0, options), 1.0);  // within the dead band
  // A focused camera's spread (1 px, 1/3 px^2 more as read) against 2.7 px, after the detector's
  // own smoothing of 1 px.
  EXPECT_NEAR(edge_blur_gain(2.7, 1.0, options),
              std::sqrt((1.0 + 1.0 + 1.0 / 3.0) / (1.0 + 2.7 * 2.7)), 1e-12);
  EXPECT_LT(edge_blur_gain(3.5, 1.0, options), edge_blur_gain(2.7, 1.0, options));
  EXPECT_EQ(edge_blur_gain(50.0, 1.0, options), options.min_gain);
}

// EDLines' response across the square's left edge, drawn through pixel centres (x = 60.5) so that
// one pixel holds the gradient's peak: that peak, and its lead over the pixels beside it (the
// anchor test's margin). The detector's own 5x5 Gaussian (sigma 1), then |Sobel x| on row 120,
// in floating point.
struct EdgeResponse {
  double peak = 0.0;
  double lead = 0.0;
};

EdgeResponse left_edge_response(double blur) {
  cv::Mat large(240 * 8, 240 * 8, CV_8U, cv::Scalar(190));
  cv::rectangle(large, cv::Rect(60 * 8 + 4, 60 * 8, 120 * 8, 120 * 8), cv::Scalar(60), cv::FILLED);
  cv::Mat frame, smoothed, gx;
  cv::resize(large, frame, cv::Size(240, 240), 0.0, 0.0, cv::INTER_AREA);
  frame.convertTo(frame, CV_32F);  // a lead of a few levels is not lost to rounding
  if (blur > 0.0) cv::GaussianBlur(frame, frame, cv::Size(0, 0), blur);
  cv::GaussianBlur(frame, smoothed, cv::Size(5, 5), 1.0);
  cv::Sobel(smoothed, gx, CV_32F, 1, 0);
  const float* row = gx.ptr<float>(120);
  EdgeResponse response;
  response.peak = std::abs(row[60]);
  response.lead = response.peak - std::max(std::abs(row[59]), std::abs(row[61]));
  return response;
}

TEST(EdgeBlurAnchorGain, FollowsTheAnchorMarginOfARenderedBlurredStep) {
  const EdgeBlurOptions options;
  EXPECT_EQ(edge_blur_anchor_gain(-1.0, 1.0, options), 1.0);  // unknown
  EXPECT_EQ(edge_blur_anchor_gain(1.9, 1.0, options), 1.0);   // within the dead band
  // The spread estimate_edge_blur reads for `blur` added to the rendered step (a 1 px box,
  // 1/12 px^2) without error: its central differences add 1/3 px^2.
  const auto read_spread = [](double blur) { return std::sqrt(blur * blur + 1.0 / 12 + 1.0 / 3); };
  const EdgeResponse sharp = left_edge_response(0.0);
  const EdgeResponse blurred = left_edge_response(2.5), more = left_edge_response(3.5);
  const double gain = edge_blur_gain(read_spread(2.5), 1.0, options);
  const double anchor_gain = edge_blur_anchor_gain(read_spread(2.5), 1.0, options);
  ASSERT_LT(gain, 1.0);  // beyond the dead band, where the ratios below hold
  // Between two blurs, the gains fall as the peak and its lead do.
  const double peak_ratio = more.peak / blurred.peak, lead_ratio = more.lead / blurred.lead;
  EXPECT_NEAR(edge_blur_gain(read_spread(3.5), 1.0, options) / gain, peak_ratio, 0.03 * peak_ratio);
  EXPECT_NEAR(edge_blur_anchor_gain(read_spread(3.5), 1.0, options) / anchor_gain, lead_ratio,
              0.03 * lead_ratio);
  // The lead falls much faster than the peak: scaled as the gradient threshold, the anchor
  // threshold would leave a blurred edge without anchors to start from.
  EXPECT_LT(blurred.lead / sharp.lead, 0.5 * blurred.peak / sharp.peak);
  EXPECT_LT(anchor_gain, 0.5 * gain);
}

TEST(EdgeBlurOptions, RejectsValuesOutOfRange) {
  EdgeBlurOptions options;
  EXPECT_NO_THROW(options.check());
  options.sharp_sigma = 0.0;
  EXPECT_THROW(options.check(), std::invalid_argument);
  options = EdgeBlurOptions();
  options.min_gain = 0.9;  // above max_gain
  EXPECT_THROW(options.check(), std::invalid_argument);
  options = EdgeBlurOptions();
  options.update_weight = 0.0;
  EXPECT_THROW(options.check(), std::invalid_argument);
  options = EdgeBlurOptions();
  options.measure_every = 0;
  EXPECT_THROW(options.check(), std::invalid_argument);
  options = EdgeBlurOptions();
  options.min_edges = options.samples + 1;
  EXPECT_THROW(options.check(), std::invalid_argument);
}

}  // namespace
}  // namespace scbt
