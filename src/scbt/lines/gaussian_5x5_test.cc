#include "scbt/lines/gaussian_5x5.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <random>
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

  // Random 0 / 255 pixels: sums of every size near every rounding step of the vertical pass.
  for (int seed = 0; seed < 20; ++seed) {
    cv::Mat binary = random_image(cv::Size(97, 61), 40 + seed);
    cv::threshold(binary, binary, 127, 255, cv::THRESH_BINARY);
    gaussian_blur_5x5(binary, &ours);
    EXPECT_EQ(differing_pixels(ours, opencv_blur(binary)), 0) << "seed " << seed;
  }
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

// Computed on a set of spans only: a pixel whose column is in the set on the rows within two of
// it comes out as the whole blur's; pixels outside the set keep their old values.
TEST(Gaussian5x5, OnSpansEqualsTheWholeBlurWhereItsRowsAreThere) {
  std::mt19937 rng(3);
  int checked = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const cv::Size size(5 + trial * 13 % 120, 5 + trial * 7 % 50);
    const cv::Mat gray = random_image(size, 100 + trial);
    RowSpans where;
    where.reset(size);
    std::uniform_int_distribution<int> column(-3, size.width + 3), length(0, size.width / 2);
    for (int r = 0; r < size.height; ++r) {
      for (int k = 0; k < 3; ++k) {
        const int first = column(rng);
        where.add(r, first, first + length(rng));
      }
    }
    cv::Mat inside;
    where.draw(&inside);
    const cv::Mat before = random_image(size, 900 + trial);
    cv::Mat ours = before.clone();
    gaussian_blur_5x5(gray, where, &ours);
    const cv::Mat whole = opencv_blur(gray);
    for (int r = 0; r < size.height; ++r) {
      for (int c = 0; c < size.width; ++c) {
        if (!inside.at<uchar>(r, c)) {
          EXPECT_EQ(ours.at<uchar>(r, c), before.at<uchar>(r, c)) << r << "," << c;
          continue;
        }
        bool rows_there = true;
        for (int q = r - 2; q <= r + 2; ++q) {
          const int reflected = q < 0 ? -q : (q >= size.height ? 2 * size.height - 2 - q : q);
          rows_there = rows_there && inside.at<uchar>(reflected, c);
        }
        if (!rows_there) continue;
        ++checked;
        EXPECT_EQ(ours.at<uchar>(r, c), whole.at<uchar>(r, c))
            << "trial " << trial << " " << r << "," << c;
      }
    }
  }
  EXPECT_GT(checked, 2000);
  RowSpans wrong;
  wrong.reset(cv::Size(3, 3));
  cv::Mat out;
  EXPECT_THROW(gaussian_blur_5x5(random_image(cv::Size(4, 4), 1), wrong, &out),
               std::invalid_argument);
}

}  // namespace
}  // namespace scbt
