#include "scbt/depth/curve_outliers.h"

#include <gtest/gtest.h>

#include <cmath>

namespace scbt {
namespace {

TEST(CurveOutliers, RemovesSpikesKeepsTrendsAndCorners) {
  // A V-shaped depth profile (a box corner nearest the camera) with two spikes and a hole.
  std::vector<double> z(60);
  for (int i = 0; i < 60; ++i) z[i] = 0.8 + 0.004 * std::abs(i - 30);
  z[10] = 1.2;
  z[45] = 0.5;
  z[20] = 0.0;
  std::vector<double> cleaned = z;
  reject_curve_outliers(DepthOptions{}, &cleaned);
  for (int i = 0; i < 60; ++i) {
    if (i == 10 || i == 45 || i == 20)
      EXPECT_EQ(cleaned[i], 0.0) << i;
    else
      EXPECT_EQ(cleaned[i], z[i]) << i;
  }
}

}  // namespace
}  // namespace scbt
