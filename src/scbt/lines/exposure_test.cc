#include "scbt/lines/exposure.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace scbt {
namespace {

// A horizontal ramp from `low` to `high` grey levels.
cv::Mat ramp(int low, int high) {
  cv::Mat image(120, 256, CV_8U);
  for (int c = 0; c < image.cols; ++c) {
    image.col(c).setTo(low + (high - low) * c / (image.cols - 1));
  }
  return image;
}

TEST(ExposureTest, SpreadIsTheMiddle96PercentOfTheGreyLevels) {
  // Uniform over 0..255: the 2nd and 98th percentiles are ~5 and ~250.
  EXPECT_NEAR(intensity_spread(ramp(0, 255), 1), 245.0, 3.0);
  EXPECT_NEAR(intensity_spread(ramp(0, 255), 8), 245.0, 8.0);
  // The same scene at 0.3x brightness.
  EXPECT_NEAR(intensity_spread(ramp(0, 76), 1), 0.3 * 245.0, 2.0);
  EXPECT_EQ(intensity_spread(cv::Mat(50, 50, CV_8U, cv::Scalar(90)), 4), 0.0);
  EXPECT_EQ(intensity_spread(cv::Mat(), 4), 0.0);
}

TEST(ExposureTest, SpreadOfColourIsThatOfItsGrey) {
  cv::Mat colour(100, 100, CV_8UC3);
  cv::randu(colour, 0, 256);
  cv::Mat grey;
  cv::cvtColor(colour, grey, cv::COLOR_BGR2GRAY);
  EXPECT_EQ(intensity_spread(colour, 3), intensity_spread(grey, 3));
  cv::Mat bgra;
  cv::cvtColor(colour, bgra, cv::COLOR_BGR2BGRA);
  EXPECT_EQ(intensity_spread(bgra, 3), intensity_spread(grey, 3));
}

TEST(ExposureTest, WellExposedFramesKeepThePublishedThresholds) {
  const ExposureOptions options;
  EXPECT_EQ(exposure_gain(245.0, options), 1.0);
  EXPECT_EQ(exposure_gain(options.full_contrast, options), 1.0);
  EXPECT_EQ(threshold_for_exposure(36, 1.0), 36);
  EXPECT_EQ(threshold_for_exposure(8, 1.0), 8);
}

TEST(ExposureTest, DimFramesScaleTheThresholdsWithTheirContrast) {
  ExposureOptions options;
  EXPECT_NEAR(exposure_gain(64.0, options), 2.0, 1e-12);
  EXPECT_EQ(threshold_for_exposure(36, 2.0), 18);
  EXPECT_EQ(threshold_for_exposure(8, 2.0), 4);
  // Capped: a flat frame is no reason to detect noise.
  EXPECT_EQ(exposure_gain(1.0, options), options.max_gain);
  EXPECT_EQ(exposure_gain(0.0, options), options.max_gain);
  EXPECT_EQ(threshold_for_exposure(8, 64.0), 1);
}

TEST(ExposureTest, BadOptionsAreRejected) {
  ExposureOptions options;
  options.full_contrast = 0.0;
  EXPECT_THROW(options.check(), std::invalid_argument);
  options = ExposureOptions();
  options.max_gain = 0.5;
  EXPECT_THROW(options.check(), std::invalid_argument);
  options = ExposureOptions();
  options.sample_step = 0;
  EXPECT_THROW(options.check(), std::invalid_argument);
  EXPECT_NO_THROW(ExposureOptions().check());
}

}  // namespace
}  // namespace scbt
