#include "scbt/motion/motion_estimate.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <random>

#include "scbt/testing/texture_test_util.h"

namespace scbt {
namespace {

// Texture smoothing (px): fine enough for a shift to the pixel.
constexpr double kTextureSigma = 2.0;

TEST(EstimateTranslation, RecoversIntegerShiftsOfATexture) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> shift(-25, 25);
  for (int trial = 0; trial < 30; ++trial) {
    const cv::Mat scene = smooth_random_texture({320, 320}, 100 + trial, kTextureSigma);
    const int dx = shift(rng), dy = shift(rng);
    const cv::Rect window(80, 80, 160, 160);
    const cv::Mat reference = scene(window);
    // The content moves by (dx, dy): the current window sees the scene at window - shift.
    const cv::Mat current = scene(window - cv::Point(dx, dy));
    const std::optional<TranslationEstimate> estimate = estimate_translation(reference, current);
    ASSERT_TRUE(estimate.has_value());
    EXPECT_NEAR(estimate->shift.x, dx, 0.5) << "trial " << trial;
    EXPECT_NEAR(estimate->shift.y, dy, 0.5) << "trial " << trial;
    EXPECT_GT(estimate->response, 0.2);
  }
}

// Windows larger than 200 px are averaged down before the correlation: the shift, scaled back,
// stays within about a pixel.
TEST(EstimateTranslation, RecoversShiftsOfLargeWindowsWithinAPixel) {
  std::mt19937 rng(9);
  std::uniform_int_distribution<int> shift(-40, 40);
  for (int trial = 0; trial < 20; ++trial) {
    const cv::Mat scene = smooth_random_texture({700, 560}, 300 + trial, kTextureSigma);
    const int dx = shift(rng), dy = shift(rng);
    const cv::Rect window(150, 120, 383 - trial, 291 + trial);
    const std::optional<TranslationEstimate> estimate =
        estimate_translation(scene(window), scene(window - cv::Point(dx, dy)));
    ASSERT_TRUE(estimate.has_value());
    EXPECT_NEAR(estimate->shift.x, dx, 1.0) << "trial " << trial;
    EXPECT_NEAR(estimate->shift.y, dy, 1.0) << "trial " << trial;
    EXPECT_GT(estimate->response, 0.2);
  }
}

// The tracker's coarse estimate (max_side 64: a 190x150 window averaged by 4) only has to tell
// a move the search band absorbs (under 5 px) from a larger one, which is then measured in full.
TEST(EstimateTranslation, CoarseEstimateTellsSmallFromLargeMoves) {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> small(-2, 2), large(8, 25), sign(0, 1);
  const cv::Rect window(100, 100, 190, 150);
  for (int trial = 0; trial < 20; ++trial) {
    const cv::Mat scene = smooth_random_texture({400, 360}, 500 + trial, kTextureSigma);
    const cv::Point still(small(rng), small(rng));
    const cv::Point moved(large(rng) * (sign(rng) ? 1 : -1), small(rng) * 4);
    const std::optional<TranslationEstimate> small_move =
        estimate_translation(scene(window), scene(window - still), 64);
    const std::optional<TranslationEstimate> large_move =
        estimate_translation(scene(window), scene(window - moved), 64);
    ASSERT_TRUE(small_move.has_value() && large_move.has_value());
    EXPECT_LT(cv::norm(small_move->shift), 5.0) << "trial " << trial << " moved " << still;
    EXPECT_GE(cv::norm(large_move->shift), 5.0) << "trial " << trial << " moved " << moved;
  }
}

// The tracker keeps one estimator: its buffers and cached window, reused across window sizes and
// resolutions, give exactly what a fresh estimate gives.
TEST(EstimateTranslation, AReusedEstimatorGivesWhatAFreshOneGives) {
  std::mt19937 rng(13);
  std::uniform_int_distribution<int> shift(-12, 12), side(60, 260);
  TranslationEstimator reused;
  for (int trial = 0; trial < 30; ++trial) {
    const cv::Mat scene = smooth_random_texture({420, 420}, 700 + trial, kTextureSigma);
    const cv::Rect window(60, 60, side(rng), side(rng));
    const cv::Mat current = scene(window - cv::Point(shift(rng), shift(rng)));
    const int max_side = trial % 3 == 0 ? 64 : 200;
    const std::optional<TranslationEstimate> fresh =
        estimate_translation(scene(window), current, max_side);
    const std::optional<TranslationEstimate> again =
        reused.estimate(scene(window), current, max_side);
    ASSERT_TRUE(fresh.has_value() && again.has_value());
    EXPECT_EQ(fresh->shift.x, again->shift.x) << "trial " << trial;
    EXPECT_EQ(fresh->shift.y, again->shift.y) << "trial " << trial;
    EXPECT_EQ(fresh->response, again->response) << "trial " << trial;
  }
}

// A full-HD window averaged down to 64 px a side (blocks of 32): the shift, scaled back, within
// the blocks' size.
TEST(EstimateTranslation, AveragesAFullHDWindowDownToTheSideAskedFor) {
  const cv::Mat scene = smooth_random_texture({2000, 1160}, 31, kTextureSigma);
  const cv::Rect window(40, 40, 1920, 1080);
  const std::optional<TranslationEstimate> estimate =
      estimate_translation(scene(window), scene(window - cv::Point(24, -16)), 64);
  ASSERT_TRUE(estimate.has_value());
  EXPECT_NEAR(estimate->shift.x, 24.0, 32.0);
  EXPECT_NEAR(estimate->shift.y, -16.0, 32.0);
}

TEST(EstimateTranslation, RejectsMismatchedOrTinyImages) {
  const cv::Mat a = smooth_random_texture({64, 64}, 1, kTextureSigma);
  EXPECT_FALSE(estimate_translation(a, a(cv::Rect(0, 0, 32, 64)).clone()).has_value());
  EXPECT_FALSE(estimate_translation(a(cv::Rect(0, 0, 8, 8)), a(cv::Rect(8, 8, 8, 8))).has_value());
  cv::Mat color;
  cv::cvtColor(a, color, cv::COLOR_GRAY2BGR);
  EXPECT_FALSE(estimate_translation(color, color).has_value());
}

}  // namespace
}  // namespace scbt
