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

int vertex_count(const std::vector<BoundarySample>& samples) {
  return static_cast<int>(std::count_if(samples.begin(), samples.end(),
                                        [](const BoundarySample& s) { return s.vertex; }));
}

bool inside(const Point& p, const SampleRegion& r) {
  return p.x >= r.x_min && p.x <= r.x_max && p.y >= r.y_min && p.y <= r.y_max;
}

// Along the edges, only the points inside the region, and the very points sampling without one
// gives there; every vertex, inside or not.
TEST(BoundarySamples, AlongTheEdgesOnlyInsideTheRegionAtTheSamePoints) {
  const Polygon polygon = {{-50.3, 20}, {90, -35.5}, {130.2, 60}, {40, 140}};
  const SampleRegion region{0, 0, 100, 80};
  const std::vector<BoundarySample> all = sample_boundary_inward(polygon, 3.0);
  const std::vector<BoundarySample> clipped = sample_boundary_inward(polygon, 3.0, region);
  std::vector<BoundarySample> expected;
  for (const BoundarySample& s : all)
    if (s.vertex || inside(s.pixel, region)) expected.push_back(s);
  ASSERT_EQ(clipped.size(), expected.size());
  EXPECT_LT(clipped.size(), all.size());
  EXPECT_EQ(vertex_count(clipped), 4);
  for (std::size_t i = 0; i < clipped.size(); ++i) {
    EXPECT_EQ(clipped[i].pixel, expected[i].pixel) << i;
    EXPECT_EQ(clipped[i].inward, expected[i].inward) << i;
    EXPECT_EQ(clipped[i].vertex, expected[i].vertex) << i;
  }
}

// A boundary around a 640x480 image 1e7 px across has its four corners as samples, and none
// along the edges: they are nowhere near the image.
TEST(BoundarySamples, APolygonFarOutsideTheRegionGivesItsVerticesOnly) {
  const Polygon huge = {{-5e6, -5e6}, {5e6, -5e6}, {5e6, 5e6}, {-5e6, 5e6}};
  const std::vector<BoundarySample> samples =
      sample_boundary_inward(huge, 3.0, SampleRegion{-10, -10, 650, 490});
  EXPECT_EQ(samples.size(), 4u);
  // An edge across the region, its ends 1e16 px away (too long to cut into 3 px pieces in a
  // double): the 660 px of it in the region, every 3 px (to the resolution of a double there).
  const Polygon across = {{-1e16, 100}, {1e16, 100}, {0, 1e16}};
  const std::vector<BoundarySample> crossing =
      sample_boundary_inward(across, 3.0, SampleRegion{-10, -10, 650, 490});
  EXPECT_GT(crossing.size(), 3u + 215u);
  EXPECT_LT(crossing.size(), 3u + 225u);
  for (const BoundarySample& s : crossing) {
    if (s.vertex) continue;
    EXPECT_TRUE(inside(s.pixel, SampleRegion{-12, 98, 652, 102})) << s.pixel.x << "," << s.pixel.y;
  }
}

// However often the boundary crosses the region, the points along its edges stay about
// max_edge_samples, spread evenly.
TEST(BoundarySamples, PointsAlongTheEdgesAreBounded) {
  Polygon comb;  // 200 teeth, each crossing the 100x100 region twice
  for (int k = 0; k < 200; ++k) {
    comb.emplace_back(0.5 * k, -1000.0);
    comb.emplace_back(0.5 * k + 0.25, 1000.0);
  }
  comb.emplace_back(100.0, 2000.0);
  const SampleRegion region{0, 0, 100, 100};
  const std::vector<BoundarySample> unbounded =
      sample_boundary_inward(comb, 1.0, region, std::size_t{1} << 30);
  EXPECT_GT(unbounded.size(), 40000u);
  const std::vector<BoundarySample> bounded = sample_boundary_inward(comb, 1.0, region, 1000);
  EXPECT_LE(bounded.size(), comb.size() + 1000 + 2 * comb.size());
  EXPECT_GE(bounded.size(), comb.size() + 900);
}

TEST(BoundarySamples, DegeneratePolygonsGiveNoSamples) {
  EXPECT_TRUE(sample_boundary_inward({{0, 0}, {5, 5}}, 2.0).empty());
  EXPECT_TRUE(sample_boundary_inward({{0, 0}, {5, 5}, {10, 10}}, 2.0).empty());
  EXPECT_TRUE(sample_boundary_inward({{0, 0}, {0, 0}, {4, 0}, {4, 0}}, 2.0).empty());
}

}  // namespace
}  // namespace scbt
