#include "scbt/geometry/boundary_query.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace scbt {
namespace {

class BoundaryQueryProperty : public ::testing::TestWithParam<unsigned> {};

// distance_to_boundary up to rounding (an edge's box can tie with the edge itself; which of two
// equal-to-the-last-bit distances wins may differ), whatever hint it starts from, for polygons of
// any shape including repeated vertices.
TEST_P(BoundaryQueryProperty, EqualsDistanceToBoundaryForAnyHint) {
  std::mt19937 rng(GetParam() * 13u + 5u);
  std::uniform_int_distribution<int> count(1, 40);
  std::uniform_real_distribution<double> coordinate(0.0, 400.0), unit(0.0, 1.0);
  Polygon polygon(count(rng));
  for (Point& p : polygon) p = Point(coordinate(rng), coordinate(rng));
  if (polygon.size() > 3 && unit(rng) < 0.3) polygon[2] = polygon[1];  // a repeated vertex
  BoundaryQuery query(polygon);
  std::uniform_int_distribution<size_t> any_hint(0, polygon.size() + 3);
  size_t hint = 0;
  for (int k = 0; k < 200; ++k) {
    const Point p(coordinate(rng) * 1.5 - 100.0, coordinate(rng) * 1.5 - 100.0);
    const double expected = distance_to_boundary(p, polygon);
    const double tolerance = 1e-12 * (1.0 + expected);
    EXPECT_NEAR(query.distance(p, &hint), expected, tolerance);
    EXPECT_LT(hint, polygon.size());
    size_t random_hint = any_hint(rng);
    EXPECT_NEAR(query.distance(p, &random_hint), expected, tolerance);
    EXPECT_NEAR(query.distance(p), expected, tolerance);
  }
  // Reset onto another polygon: answers follow it.
  Polygon other = {{10, 10}, {20, 10}, {20, 20}};
  query.reset(other);
  EXPECT_EQ(query.distance(Point(15, 0)), 10.0);
}

INSTANTIATE_TEST_SUITE_P(Seeds, BoundaryQueryProperty, ::testing::Range(0u, 100u));

// The answer and the nearest edge a query returns, to the last bit, are those of the plain scan:
// the hint edge first, then every edge in order, an edge's exact distance computed only when its
// box is nearer than the best so far. Callers (the stabilised choice) compare sums of these
// distances, so the result must not depend on how the box test is computed. Polygons of up to
// 300 edges cover queries that span several blocks of boxes.
struct PlainAnswer {
  double distance;
  size_t nearest;
};
PlainAnswer plain_scan(const Point& p, const Polygon& polygon, size_t hint) {
  const size_t n = polygon.size();
  auto edge = [&](size_t i) {
    return distance_sq_to_segment(p, polygon[i == 0 ? n - 1 : i - 1], polygon[i]);
  };
  size_t nearest = hint < n ? hint : 0;
  double best = edge(nearest);
  for (size_t i = 0; i < n; ++i) {
    const Point& a = polygon[i == 0 ? n - 1 : i - 1];
    const Point& b = polygon[i];
    const double dx = std::max({std::min(a.x, b.x) - p.x, 0.0, p.x - std::max(a.x, b.x)});
    const double dy = std::max({std::min(a.y, b.y) - p.y, 0.0, p.y - std::max(a.y, b.y)});
    if (dx * dx + dy * dy >= best) continue;
    const double d = edge(i);
    if (d < best) {
      best = d;
      nearest = i;
    }
  }
  return {std::sqrt(best), nearest};
}

TEST_P(BoundaryQueryProperty, SameBitsAndNearestEdgeAsThePlainScan) {
  std::mt19937 rng(GetParam() * 31u + 7u);
  std::uniform_int_distribution<int> count(2, 300);
  std::uniform_real_distribution<double> angle(0.0, 6.283185307179586), radius(50.0, 150.0);
  // A star-shaped boundary around (200, 200): many edges near any point, as a tracked boundary.
  Polygon polygon(count(rng));
  std::vector<double> angles(polygon.size());
  for (double& t : angles) t = angle(rng);
  std::sort(angles.begin(), angles.end());
  for (size_t i = 0; i < polygon.size(); ++i) {
    const double r = radius(rng);
    polygon[i] = Point(200.0 + r * std::cos(angles[i]), 200.0 + r * std::sin(angles[i]));
  }
  const BoundaryQuery query(polygon);
  std::uniform_real_distribution<double> coordinate(0.0, 400.0);
  size_t hint = 0;
  for (int k = 0; k < 300; ++k) {
    const Point p(coordinate(rng), coordinate(rng));
    const PlainAnswer expected = plain_scan(p, polygon, hint);
    EXPECT_EQ(query.distance(p, &hint), expected.distance);
    EXPECT_EQ(hint, expected.nearest);
  }
}

}  // namespace
}  // namespace scbt
