#include "scbt/tracker/contrast_profile.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace scbt {
namespace {

Polygon square(Point centre, double half) {
  return {centre + Point(-half, -half), centre + Point(half, -half), centre + Point(half, half),
          centre + Point(-half, half)};
}

// A grey frame with a bright square and a darker bar beside it (so that the profile is not
// constant along the boundary), the square's centre at `centre`.
cv::Mat scene(Point centre, int channels = 1) {
  cv::Mat image(200, 240, CV_8UC1, cv::Scalar(60));
  cv::rectangle(image, cv::Point(static_cast<int>(centre.x) - 30, static_cast<int>(centre.y) - 30),
                cv::Point(static_cast<int>(centre.x) + 30, static_cast<int>(centre.y) + 30),
                cv::Scalar(200), cv::FILLED);
  cv::rectangle(image, cv::Point(static_cast<int>(centre.x) + 31, static_cast<int>(centre.y) - 30),
                cv::Point(static_cast<int>(centre.x) + 60, static_cast<int>(centre.y)),
                cv::Scalar(20), cv::FILLED);
  if (channels == 3) cv::cvtColor(image, image, cv::COLOR_GRAY2BGR);
  return image;
}

TEST(ContrastProfile, SignFollowsTheContrastAcrossTheBoundary) {
  std::vector<float> profile;
  contrast_profile(scene({100, 100}), square({100, 100}, 30.5), {}, &profile);
  ASSERT_EQ(profile.size(), 64u);
  // Everything around the square is darker than it: every sample has the same sign.
  int positive = 0, negative = 0;
  for (float v : profile) (v > 0 ? positive : negative) += v != 0.0f ? 1 : 0;
  EXPECT_TRUE(positive == 0 || negative == 0) << positive << " / " << negative;
  for (float v : profile) EXPECT_GT(std::abs(v), 100.0f);  // 200 vs 60 or 20: > 100 everywhere
}

TEST(ContrastProfile, ColourIsReadAsGrey) {
  std::vector<float> grey, colour;
  contrast_profile(scene({100, 100}), square({100, 100}, 30.5), {}, &grey);
  contrast_profile(scene({100, 100}, 3), square({100, 100}, 30.5), {}, &colour);
  ASSERT_EQ(grey.size(), colour.size());
  for (size_t i = 0; i < grey.size(); ++i) EXPECT_NEAR(grey[i], colour[i], 1.0);
}

TEST(ContrastProfile, ColourIsWeightedByBT601) {
  // Two colours, one inside a rectangle and one around it, read one pixel at a time (no
  // smoothing): each sample is the difference of their grey levels, or 0 where both reads fall on
  // one side (at the corners).
  cv::RNG rng(11);
  for (int trial = 0; trial < 20; ++trial) {
    const cv::Vec3b a(rng.uniform(0, 256), rng.uniform(0, 256), rng.uniform(0, 256));
    const cv::Vec3b b(rng.uniform(0, 256), rng.uniform(0, 256), rng.uniform(0, 256));
    cv::Mat image(100, 100, CV_8UC3, cv::Scalar(a[0], a[1], a[2]));
    image(cv::Rect(30, 20, 40, 60)).setTo(cv::Scalar(b[0], b[1], b[2]));
    const auto grey = [](const cv::Vec3b& c) { return 0.114 * c[0] + 0.587 * c[1] + 0.299 * c[2]; };
    const float step = static_cast<float>(grey(a) - grey(b));
    ContrastProfileOptions options;
    options.smoothing = 0;
    std::vector<float> profile;
    contrast_profile(image, {{29.5, 19.5}, {69.5, 19.5}, {69.5, 79.5}, {29.5, 79.5}}, options,
                     &profile);
    int across = 0;
    for (float v : profile) {
      EXPECT_TRUE(v == 0.0f || v == step || v == -step) << v << " vs " << step;
      across += v != 0.0f || step == 0.0f ? 1 : 0;
    }
    EXPECT_GT(across, 48);
  }
}

TEST(BoundaryAppearance, PrefersThePlacementWhereTheBoundaryMovedTo) {
  BoundaryAppearance appearance;
  appearance.remember(scene({100, 100}), square({100, 100}, 30.5));
  const cv::Mat moved = scene({112, 95});
  const double stayed = appearance.agreement(moved, square({100, 100}, 30.5));
  const double followed = appearance.agreement(moved, square({112, 95}, 30.5));
  EXPECT_GT(followed, 0.99);
  EXPECT_LT(stayed, followed - 0.3);
}

TEST(BoundaryAppearance, NoiseDoesNotHideTheBoundary) {
  BoundaryAppearance appearance;
  appearance.remember(scene({100, 100}), square({100, 100}, 30.5));
  cv::Mat noisy = scene({112, 95});
  cv::Mat noise(noisy.size(), CV_16SC1);
  cv::RNG rng(7);
  rng.fill(noise, cv::RNG::NORMAL, 0, 25);
  cv::Mat sum;
  noisy.convertTo(sum, CV_16SC1);
  sum += noise;
  sum.convertTo(noisy, CV_8UC1);
  EXPECT_GT(appearance.agreement(noisy, square({112, 95}, 30.5)),
            appearance.agreement(noisy, square({100, 100}, 30.5)) + 0.3);
}

TEST(ContrastProfile, AgreementIsACosine) {
  EXPECT_DOUBLE_EQ(profile_agreement({1, 2, 3}, {2, 4, 6}), 1.0);
  EXPECT_DOUBLE_EQ(profile_agreement({1, 2, 3}, {-1, -2, -3}), -1.0);
  EXPECT_DOUBLE_EQ(profile_agreement({1, 0}, {0, 1}), 0.0);
  EXPECT_DOUBLE_EQ(profile_agreement({0, 0}, {0, 1}), 0.0);     // flat
  EXPECT_DOUBLE_EQ(profile_agreement({1, 2}, {1, 2, 3}), 0.0);  // lengths differ
  BoundaryAppearance empty;
  EXPECT_DOUBLE_EQ(empty.agreement(scene({100, 100}), square({100, 100}, 30.5)), 0.0);
}

TEST(ContrastProfile, RejectsBadInputAndOptions) {
  std::vector<float> profile;
  EXPECT_THROW(contrast_profile(cv::Mat(10, 10, CV_32FC1), square({5, 5}, 2), {}, &profile),
               std::invalid_argument);
  ContrastProfileOptions options;
  options.samples = 2;
  EXPECT_THROW(options.check(), std::invalid_argument);
  options = {};
  options.across = 0.0;
  EXPECT_THROW(options.check(), std::invalid_argument);
  options = {};
  options.smoothing = -1;
  EXPECT_THROW(options.check(), std::invalid_argument);
  EXPECT_NO_THROW(ContrastProfileOptions().check());
}

}  // namespace
}  // namespace scbt
