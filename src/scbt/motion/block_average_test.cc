#include "scbt/motion/block_average.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace scbt {
namespace {

// It computes cv::resize's INTER_AREA of the full blocks, to the bit, on noise (many ties) and on
// smooth images, at every factor the motion estimate uses.
TEST(AverageBlocks, EqualsOpenCVsAreaResize) {
  cv::RNG rng(7);
  for (const int factor : {2, 4, 8, 16, 32, 64}) {
    for (int trial = 0; trial < 12; ++trial) {
      const int rows = rng.uniform(factor, 1080), cols = rng.uniform(factor, 1920);
      cv::Mat gray(rows, cols, CV_8U);
      rng.fill(gray, cv::RNG::UNIFORM, 0, 256);
      if (trial % 2 == 1) cv::GaussianBlur(gray, gray, cv::Size(0, 0), 3.0);
      const cv::Size small(cols / factor, rows / factor);
      cv::Mat expected, ours;
      cv::resize(gray(cv::Rect(0, 0, small.width * factor, small.height * factor)), expected, small,
                 0.0, 0.0, cv::INTER_AREA);
      average_blocks(gray, factor, &ours);
      ASSERT_EQ(ours.size(), small);
      EXPECT_EQ(cv::countNonZero(ours != expected), 0)
          << "factor " << factor << ", " << gray.size();
    }
  }
}

TEST(AverageBlocks, RejectsWhatItCannotAverage) {
  cv::Mat averaged;
  const cv::Mat gray(64, 64, CV_8U, cv::Scalar(9));
  EXPECT_THROW(average_blocks(gray, 3, &averaged), std::invalid_argument);
  EXPECT_THROW(average_blocks(gray, 1, &averaged), std::invalid_argument);
  EXPECT_THROW(average_blocks(gray, 2 * kMaxFactor, &averaged), std::invalid_argument);
  EXPECT_THROW(average_blocks(cv::Mat(64, 64, CV_8UC3), 2, &averaged), std::invalid_argument);
  average_blocks(gray, 4, &averaged);
  EXPECT_EQ(averaged.size(), cv::Size(16, 16));
  EXPECT_EQ(averaged.at<std::uint8_t>(3, 5), 9);
}

}  // namespace
}  // namespace scbt
