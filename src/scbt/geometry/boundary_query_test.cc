#include "scbt/geometry/boundary_query.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

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

}  // namespace
}  // namespace scbt
