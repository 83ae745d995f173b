#include "scbt/tracker/view_cut.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <vector>

#include "scbt/testing/texture_test_util.h"

namespace scbt {
namespace {

// Texture smoothing (px): coarse enough to survive the 32 x 32 thumbnails.
constexpr double kTextureSigma = 4.0;

// A window of 160 x 110 px, as the tracker keeps around an object of 100 x 60 px.
const cv::Rect kWindow(100, 100, 160, 110);
const Polygon kObject{{30.0, 25.0}, {130.0, 25.0}, {130.0, 85.0}, {30.0, 85.0}};

// `scene` with the (flat, bright) object painted where kObject lies in kWindow.
cv::Mat with_object(const cv::Mat& scene) {
  cv::Mat out = scene.clone();
  std::vector<cv::Point> corners;
  for (const Point& p : kObject)
    corners.emplace_back(cvRound(p.x) + kWindow.x, cvRound(p.y) + kWindow.y);
  cv::fillPoly(out, std::vector<std::vector<cv::Point>>{corners}, cv::Scalar(230));
  return out;
}

// The camera turned a little: object and surroundings moved together.
TEST(CoarseViewCorrelation, TheSameViewMovedAFewPixelsIsAlike) {
  const cv::Mat scene = with_object(smooth_random_texture({480, 360}, 3, kTextureSigma));
  const cv::Mat reference = scene(kWindow);
  const cv::Mat current = scene(kWindow + cv::Point(12, -8));
  EXPECT_GT(coarse_view_correlation(reference, current), 0.9);
  EXPECT_GT(surroundings_correlation(reference, current, kObject), 0.9);
}

TEST(CoarseViewCorrelation, AnotherViewIsNotAlike) {
  const cv::Mat reference =
      with_object(smooth_random_texture({480, 360}, 3, kTextureSigma))(kWindow);
  const cv::Mat other = smooth_random_texture({480, 360}, 4, kTextureSigma)(kWindow);
  EXPECT_LT(coarse_view_correlation(reference, other), 0.6);
  EXPECT_LT(surroundings_correlation(reference, other, kObject), 0.6);
}

// The surroundings moved far away (a cut) while a look-alike sits where the object was: the whole
// window stays alike (the bright object dominates it), the surroundings without it do not.
TEST(CoarseViewCorrelation, ALookAlikeInPlaceIsToldByTheSurroundings) {
  const cv::Mat scene = smooth_random_texture({480, 360}, 5, kTextureSigma);
  const cv::Mat reference = with_object(scene)(kWindow);
  // The look-alike at the object's place in the window; the surroundings from 150 px away.
  cv::Mat moved = scene.clone();
  scene(kWindow + cv::Point(140, 60)).copyTo(moved(kWindow));
  const cv::Mat cut = with_object(moved)(kWindow);
  EXPECT_GT(coarse_view_correlation(reference, cut), 0.8);
  EXPECT_LT(surroundings_correlation(reference, cut, kObject), 0.6);
}

// On a plain background (camera noise only) the surroundings say nothing: only the whole window
// can tell a cut.
TEST(CoarseViewCorrelation, FlatSurroundingsAreAlike) {
  cv::Mat plain(360, 480, CV_8U, cv::Scalar(128));
  cv::Mat noise(plain.size(), CV_8U);
  cv::RNG(9).fill(noise, cv::RNG::NORMAL, 0, 3);
  const cv::Mat scene = with_object(plain + noise);
  const cv::Mat reference = scene(kWindow);
  const cv::Mat current = scene(kWindow + cv::Point(6, 4));
  EXPECT_EQ(surroundings_correlation(reference, current, kObject), 1.0);
  EXPECT_GT(coarse_view_correlation(reference, current), 0.9);
}

TEST(CoarseViewCorrelation, AFlatViewIsNotAlike) {
  const cv::Mat reference =
      with_object(smooth_random_texture({480, 360}, 3, kTextureSigma))(kWindow);
  const cv::Mat grey(kWindow.size(), CV_8U, cv::Scalar(128));
  EXPECT_EQ(coarse_view_correlation(reference, grey), 0.0);
  EXPECT_EQ(surroundings_correlation(reference, grey, kObject), 0.0);
}

}  // namespace
}  // namespace scbt
