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

TEST(ExposureTest, WellExposedFramesAreNotStretched) {
  const ExposureOptions options;
  EXPECT_EQ(exposure_gain(245.0, options), 1.0);
  EXPECT_EQ(exposure_gain(options.full_contrast, options), 1.0);
  const GreyStretch none = grey_stretch(1.0, IntensityLevels{30, 40, 200, 210});
  EXPECT_EQ(none.gain, 1.0);
  EXPECT_EQ(none.offset, 0.0);
  EXPECT_EQ(none.residual, 1.0);
  cv::Mat gray = ramp(0, 255);
  const cv::Mat before = gray.clone();
  apply_grey_stretch(none, &gray);
  EXPECT_EQ(cv::norm(gray, before, cv::NORM_INF), 0.0);
}

TEST(ExposureTest, DimFramesAreStretchedToTheFullContrast) {
  ExposureOptions options;
  EXPECT_NEAR(exposure_gain(64.0, options), 2.0, 1e-12);
  // Capped: a flat frame is no reason to detect noise.
  EXPECT_EQ(exposure_gain(1.0, options), options.max_gain);
  EXPECT_EQ(exposure_gain(0.0, options), options.max_gain);
  // A frame at 30 % of the light: its spread, read again after the stretch, is the full contrast,
  // and nothing saturates.
  cv::Mat gray = ramp(0, 76);
  IntensityLevels levels;
  const double spread = intensity_spread(gray, 1, &levels);
  EXPECT_LE(levels.darkest, levels.low);
  EXPECT_LE(levels.low, 3);
  EXPECT_GE(levels.brightest, levels.high);
  const GreyStretch stretch = grey_stretch(exposure_gain(spread, options), levels);
  EXPECT_EQ(stretch.residual, 1.0);
  apply_grey_stretch(stretch, &gray);
  EXPECT_NEAR(intensity_spread(gray, 1), options.full_contrast, 2.0);
  double lowest = 0.0, highest = 0.0;
  cv::minMaxLoc(gray, &lowest, &highest);
  EXPECT_GT(lowest, 0.0);
  EXPECT_LT(highest, 255.0);
  // A level read on the stretched frame, in the frame's own levels.
  EXPECT_NEAR(unstretched_level(stretch, stretch.gain * 50.0 + stretch.offset), 50.0, 1e-9);
  EXPECT_EQ(unstretched_level(stretch, -1.0), -1.0);
}

// A dim frame with a bright spot: the stretch stops where the spot would saturate, and the
// thresholds are scaled by the gain it leaves.
TEST(ExposureTest, AStretchThatWouldSaturateLeavesTheRestToTheThresholds) {
  ExposureOptions options;
  cv::Mat gray = ramp(20, 60);
  gray(cv::Rect(0, 0, 20, 15)).setTo(250);  // 1 % of the frame
  IntensityLevels levels;
  const double spread = intensity_spread(gray, 1, &levels);
  const double gain = exposure_gain(spread, options);
  const GreyStretch stretch = grey_stretch(gain, levels);
  EXPECT_LT(stretch.gain, gain);
  EXPECT_NEAR(stretch.gain * stretch.residual, gain, 1e-9);
  const cv::Mat before = gray.clone();
  apply_grey_stretch(stretch, &gray);
  // Nothing clipped: every level maps back to where it was (to the rounding).
  cv::Mat back;
  gray.convertTo(back, CV_64F, 1.0 / stretch.gain, -stretch.offset / stretch.gain);
  cv::Mat original;
  before.convertTo(original, CV_64F);
  EXPECT_LE(cv::norm(back, original, cv::NORM_INF), 0.5 / stretch.gain + 1e-9);
  EXPECT_EQ(threshold_for_exposure(36, 1.0), 36);
  EXPECT_EQ(threshold_for_exposure(8, 2.0), 4);
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
