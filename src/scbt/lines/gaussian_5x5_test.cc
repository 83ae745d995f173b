#include "scbt/lines/gaussian_5x5.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace scbt {
namespace {

cv::Mat random_image(cv::Size size, int seed) {
  cv::Mat image(size, CV_8UC1);
  cv::RNG rng(seed);
  rng.fill(image, cv::RNG::UNIFORM, 0, 256);
  return image;
}

cv::Mat opencv_blur(const cv::Mat& gray) {
  cv::Mat out;
  cv::GaussianBlur(gray, out, cv::Size(5, 5), 1.0, 1.0);
  return out;
}

int differing_pixels(const cv::Mat& a, const cv::Mat& b) {
  EXPECT_EQ(a.size(), b.size());
  EXPECT_EQ(a.type(), b.type());
  return cv::countNonZero(a != b);
}

TEST(Gaussian5x5, MatchesOpenCvBitForBitOnRandomImagesOfEverySmallSize) {
  int seed = 1;
  for (int rows = 1; rows <= 9; ++rows) {
    for (int cols = 1; cols <= 9; ++cols) {
      const cv::Mat gray = random_image(cv::Size(cols, rows), seed++);
      cv::Mat ours;
      gaussian_blur_5x5(gray, &ours);
      EXPECT_EQ(differing_pixels(ours, opencv_blur(gray)), 0) << cols << "x" << rows;
    }
  }
}

TEST(Gaussian5x5, MatchesOpenCvOnFrameSizedNoiseAndOnExtremes) {
  const cv::Mat noise = random_image(cv::Size(640, 480), 7);
  cv::Mat ours;
  gaussian_blur_5x5(noise, &ours);
  EXPECT_EQ(differing_pixels(ours, opencv_blur(noise)), 0);

  // All 255 (the largest sums) and a checkerboard of 0 and 255 (the largest differences).
  const cv::Mat white(37, 53, CV_8UC1, cv::Scalar(255));
  gaussian_blur_5x5(white, &ours);
  EXPECT_EQ(differing_pixels(ours, white), 0);
  cv::Mat checker(37, 53, CV_8UC1);
  for (int r = 0; r < checker.rows; ++r) {
    for (int c = 0; c < checker.cols; ++c) checker.at<uchar>(r, c) = ((r + c) % 2) * 255;
  }
  gaussian_blur_5x5(checker, &ours);
  EXPECT_EQ(differing_pixels(ours, opencv_blur(checker)), 0);
}

TEST(Gaussian5x5, AViewIsSmoothedAsItsOwnImage) {
  // OpenCV's blur of a view reads the pixels around it; ours sees only the view's pixels, as
  // OpenCV's blur of the view's copy does.
  const cv::Mat frame = random_image(cv::Size(200, 150), 3);
  const cv::Mat view = frame(cv::Rect(31, 17, 101, 77));
  ASSERT_FALSE(view.isContinuous());
  cv::Mat ours;
  gaussian_blur_5x5(view, &ours);
  EXPECT_EQ(differing_pixels(ours, opencv_blur(view.clone())), 0);
}

TEST(Gaussian5x5, ReusesTheOutputAndRejectsOtherTypes) {
  cv::Mat out(10, 10, CV_8UC1);
  const uchar* before = out.data;
  gaussian_blur_5x5(random_image(cv::Size(10, 10), 5), &out);
  EXPECT_EQ(out.data, before);
  cv::Mat empty;
  gaussian_blur_5x5(cv::Mat(0, 0, CV_8UC1), &empty);
  EXPECT_TRUE(empty.empty());
  EXPECT_THROW(gaussian_blur_5x5(cv::Mat(4, 4, CV_8UC3), &out), std::invalid_argument);
  EXPECT_THROW(gaussian_blur_5x5(cv::Mat(4, 4, CV_16UC1), &out), std::invalid_argument);
}

}  // namespace
}  // namespace scbt
