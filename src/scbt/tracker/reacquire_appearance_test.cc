// The colour histogram of the band inside a boundary: the same object larger, turned, elsewhere
// or with other contents looks the same; another colour, or another grey, does not.
#include "scbt/tracker/reacquire_appearance.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

namespace scbt {
namespace {

Polygon square(Point center, double half) {
  return {center + Point(-half, -half), center + Point(half, -half), center + Point(half, half),
          center + Point(-half, half)};
}

void fill(cv::Mat* image, const Polygon& polygon, const cv::Scalar& colour) {
  std::vector<cv::Point> points;
  for (const Point& p : polygon) points.emplace_back(cvRound(p.x), cvRound(p.y));
  cv::fillPoly(*image, std::vector<std::vector<cv::Point>>{points}, colour);
}

TEST(ReacquireAppearanceTest, TheSameObjectElsewhereAndLargerLooksTheSame) {
  cv::Mat image(240, 320, CV_8UC3, cv::Scalar(40, 90, 60));
  const Polygon small = square({80, 80}, 30), large = square({220, 150}, 60);
  // A two-coloured object: its left half orange, its right half blue, at two sizes.
  for (const Polygon* p : {&small, &large}) {
    fill(&image, *p, cv::Scalar(30, 140, 230));
    const Point c = centroid(*p);
    const double half = (*p)[1].x - c.x;
    fill(&image, {c + Point(0, -half), (*p)[1], (*p)[2], c + Point(0, half)},
         cv::Scalar(200, 80, 20));
  }
  const RegionHistogram a = region_histogram(image, small), b = region_histogram(image, large);
  ASSERT_EQ(a.bins.size(), 64u);
  EXPECT_GT(histogram_similarity(a, b), 0.98);
  EXPECT_NEAR(histogram_similarity(a, a), 1.0, 1e-6);

  // The background's colour inside the same outline: nothing in common.
  const RegionHistogram elsewhere = region_histogram(image, square({160, 40}, 15));
  EXPECT_LT(histogram_similarity(a, elsewhere), 0.1);
}

TEST(ReacquireAppearanceTest, OtherContentsInsideTheSameWallLookTheSame) {
  // A white cup with tea in it, and the same cup emptied and seen smaller elsewhere: the middle
  // (0.7 of the size: half the area) changes colour, the wall does not.
  cv::Mat image(240, 320, CV_8UC3, cv::Scalar(40, 90, 60));
  const Polygon full = square({80, 80}, 50), empty = square({230, 150}, 35);
  fill(&image, full, cv::Scalar(235, 235, 235));
  fill(&image, square({80, 80}, 35), cv::Scalar(20, 60, 110));
  fill(&image, empty, cv::Scalar(235, 235, 235));
  fill(&image, square({230, 150}, 24.5), cv::Scalar(180, 190, 200));
  EXPECT_GT(histogram_similarity(region_histogram(image, full), region_histogram(image, empty)),
            0.95);
}

TEST(ReacquireAppearanceTest, GreyImagesCompareGreyLevels) {
  cv::Mat image(200, 200, CV_8UC1, cv::Scalar(60));
  fill(&image, square({50, 50}, 30), cv::Scalar(215));
  fill(&image, square({140, 140}, 40), cv::Scalar(115));
  const RegionHistogram bright = region_histogram(image, square({50, 50}, 30));
  const RegionHistogram dark = region_histogram(image, square({140, 140}, 40));
  ASSERT_EQ(bright.bins.size(), 16u);
  EXPECT_LT(histogram_similarity(bright, dark), 0.1);
  // Colour against grey, nothing inside, or no image: no similarity.
  cv::Mat colour;
  cv::cvtColor(image, colour, cv::COLOR_GRAY2BGR);
  EXPECT_EQ(histogram_similarity(bright, region_histogram(colour, square({50, 50}, 30))), 0.0);
  EXPECT_TRUE(region_histogram(image, square({50, 50}, 1)).bins.empty());
  EXPECT_TRUE(region_histogram(cv::Mat(), square({50, 50}, 30)).bins.empty());
}

}  // namespace
}  // namespace scbt
