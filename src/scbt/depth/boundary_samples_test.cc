#include "scbt/depth/boundary_samples.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace scbt {
namespace {

TEST(BoundarySamples, InwardNormalsPointIntoTheRegionForBothOrientations) {
  Polygon square = {{10, 10}, {50, 10}, {50, 50}, {10, 50}};
  for (int orientation = 0; orientation < 2; ++orientation) {
    const std::vector<BoundarySample> samples = sample_boundary_inward(square, 3.0);
    ASSERT_GE(samples.size(), 4u * 13u);
    EXPECT_EQ(std::count_if(samples.begin(), samples.end(),
                            [](const BoundarySample& s) { return s.vertex; }),
              4);
    for (const BoundarySample& s : samples) {
      const Point inside = s.pixel + s.inward * 2.0;
      EXPECT_TRUE(inside.x > 10 && inside.x < 50 && inside.y > 10 && inside.y < 50)
          << s.pixel.x << "," << s.pixel.y;
      EXPECT_NEAR(std::hypot(s.inward.x, s.inward.y), 1.0, 1e-12);
    }
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const Point d = samples[(i + 1) % samples.size()].pixel - samples[i].pixel;
      EXPECT_LE(std::hypot(d.x, d.y), 3.0 + 1e-9);
    }
    std::reverse(square.begin(), square.end());
  }
}

TEST(BoundarySamples, DegeneratePolygonsGiveNoSamples) {
  EXPECT_TRUE(sample_boundary_inward({{0, 0}, {5, 5}}, 2.0).empty());
  EXPECT_TRUE(sample_boundary_inward({{0, 0}, {5, 5}, {10, 10}}, 2.0).empty());
  EXPECT_TRUE(sample_boundary_inward({{0, 0}, {0, 0}, {4, 0}, {4, 0}}, 2.0).empty());
}

}  // namespace
}  // namespace scbt
