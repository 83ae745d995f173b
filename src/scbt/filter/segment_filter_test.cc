// The distance filter against an independent brute-force computation.
#include "scbt/filter/segment_filter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace scbt {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Distance from p to segment [a, b], written independently of the library: project, clamp,
// measure.
double reference_point_segment(const Point& p, const Point& a, const Point& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double len2 = dx * dx + dy * dy;
  double t = 0.0;
  if (len2 > 0.0) t = ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2;
  t = std::max(0.0, std::min(1.0, t));
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

double reference_boundary_distance(const Point& p, const Polygon& polygon) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < polygon.size(); ++i) {
    best =
        std::min(best, reference_point_segment(p, polygon[i], polygon[(i + 1) % polygon.size()]));
  }
  return best;
}

double reference_mean(const Segment& s, const Polygon& polygon) {
  const Point mid((s.a.x + s.b.x) / 2.0, (s.a.y + s.b.y) / 2.0);
  return (reference_boundary_distance(s.a, polygon) + reference_boundary_distance(s.b, polygon) +
          reference_boundary_distance(mid, polygon)) /
         3.0;
}

Polygon random_polygon(std::mt19937& rng) {
  std::uniform_int_distribution<int> count(3, 16);
  std::uniform_real_distribution<double> radius(40.0, 150.0), jitter(0.1, 0.9);
  const int n = count(rng);
  Polygon polygon;
  for (int i = 0; i < n; ++i) {
    const double angle = 2.0 * kPi * (i + jitter(rng)) / n;
    const double r = radius(rng);
    polygon.emplace_back(320.0 + r * std::cos(angle), 240.0 + r * std::sin(angle));
  }
  return polygon;
}

class SegmentFilterProperty : public ::testing::TestWithParam<unsigned> {};

TEST_P(SegmentFilterProperty, KeepsExactlyTheSegmentsBelowTheBound) {
  std::mt19937 rng(GetParam() * 31u + 7u);
  const Polygon boundary = random_polygon(rng);
  std::uniform_real_distribution<double> x(100.0, 540.0), y(20.0, 460.0), len(1.0, 60.0),
      angle(-kPi, kPi), bound(1.0, 40.0);
  std::vector<Segment> segments;
  // Half of the segments start on the boundary, so that the bound actually splits them.
  std::uniform_int_distribution<size_t> edge(0, boundary.size() - 1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 80; ++i) {
    Point a;
    if (i % 2 == 0) {
      const size_t k = edge(rng);
      a = boundary[k] + (boundary[(k + 1) % boundary.size()] - boundary[k]) * unit(rng);
    } else {
      a = Point(x(rng), y(rng));
    }
    const double t = angle(rng), l = len(rng);
    segments.push_back({a, a + Point(std::cos(t), std::sin(t)) * l});
  }
  const double max_mean = bound(rng);

  std::vector<Segment> expected;
  for (const Segment& s : segments) {
    const double reference = reference_mean(s, boundary);
    EXPECT_NEAR(mean_distance_to_boundary(s, boundary), reference, 1e-9);
    // Skip the (measure-zero) cases where rounding could decide.
    if (std::abs(reference - max_mean) < 1e-9) continue;
    if (reference < max_mean) expected.push_back(s);
  }
  const std::vector<Segment> kept = filter_segments_near_boundary(segments, boundary, max_mean);
  ASSERT_EQ(kept.size(), expected.size());
  for (size_t i = 0; i < kept.size(); ++i) {  // same segments, input order kept
    EXPECT_EQ(kept[i].a, expected[i].a);
    EXPECT_EQ(kept[i].b, expected[i].b);
  }
  EXPECT_GT(kept.size(), 0u);
  EXPECT_LT(kept.size(), segments.size());

  // With distances: the same segments, and each one's endpoint and midpoint distances exactly
  // distance_to_boundary's (the boundary choice takes them in place of its own).
  std::vector<Segment> kept_again = {segments[0]};
  std::vector<double> distances = {-1.0};
  filter_segments_near_boundary(segments, boundary, max_mean, &kept_again, &distances);
  ASSERT_EQ(kept_again.size(), kept.size());
  ASSERT_EQ(distances.size(), 3 * kept.size());
  for (size_t i = 0; i < kept.size(); ++i) {
    EXPECT_EQ(kept_again[i].a, kept[i].a);
    EXPECT_EQ(distances[3 * i], distance_to_boundary(kept[i].a, boundary));
    EXPECT_EQ(distances[3 * i + 1], distance_to_boundary(kept[i].b, boundary));
    EXPECT_EQ(distances[3 * i + 2], distance_to_boundary(kept[i].midpoint(), boundary));
  }
}

INSTANTIATE_TEST_SUITE_P(Seeds, SegmentFilterProperty, ::testing::Range(0u, 100u));

TEST(SegmentFilter, BoundIsStrict) {
  const Polygon square{{0, 0}, {100, 0}, {100, 100}, {0, 100}};
  // A segment parallel to the bottom edge, 5 px below it: mean distance exactly 5.
  const Segment below{{20, -5}, {60, -5}};
  EXPECT_DOUBLE_EQ(mean_distance_to_boundary(below, square), 5.0);
  EXPECT_TRUE(filter_segments_near_boundary({below}, square, 5.0).empty());
  EXPECT_EQ(filter_segments_near_boundary({below}, square, 5.0 + 1e-9).size(), 1u);
  // A segment from the edge straight outwards: distances 0, 6 and 3 -> mean 3.
  const Segment outwards{{50, 100}, {50, 106}};
  EXPECT_DOUBLE_EQ(mean_distance_to_boundary(outwards, square), 3.0);
  EXPECT_TRUE(filter_segments_near_boundary({outwards}, square, 3.0).empty());
  EXPECT_EQ(filter_segments_near_boundary({outwards, below}, square, 4.0).size(), 1u);
  EXPECT_TRUE(filter_segments_near_boundary({}, square, 4.0).empty());
}

}  // namespace
}  // namespace scbt
