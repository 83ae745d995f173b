#include "scbt/geometry/segment_distance_row.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

namespace scbt {
namespace {

uint64_t bits(double v) {
  uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

// Every value equal to distance_sq_to_segment's to the last bit, for each count (odd ones end
// on the scalar path), segment (zero-length ones included) and point beyond either end.
void expect_row_matches(const std::vector<Point>& points, const Point& a, const Point& b) {
  std::vector<double> x, y;
  for (const Point& p : points) {
    x.push_back(p.x);
    y.push_back(p.y);
  }
  for (size_t count = 0; count <= points.size(); ++count) {
    std::vector<double> out(count + 1, -1.0);
    distance_sq_row_to_segment(x.data(), y.data(), count, a, b, out.data());
    for (size_t s = 0; s < count; ++s) {
      EXPECT_EQ(bits(out[s]), bits(distance_sq_to_segment(points[s], a, b)))
          << "point " << s << " of " << count;
    }
    EXPECT_EQ(out[count], -1.0) << "wrote past the end";
  }
}

TEST(DistanceSqRowToSegment, MatchesDistanceSqToSegmentBitForBit) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(-50.0, 450.0);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Point> points(9);
    for (Point& p : points) p = Point(coordinate(rng), coordinate(rng));
    const Point a(coordinate(rng), coordinate(rng));
    const Point b = trial % 10 == 0 ? a : Point(coordinate(rng), coordinate(rng));
    // Points at and on the line through the segment's ends, where t is exactly 0 or 1.
    points[0] = a;
    points[1] = b;
    points[2] = a + 2.0 * (a - b);
    expect_row_matches(points, a, b);
  }
}

TEST(DistanceSqRowToSegment, SignedZerosAndAxisAlignedSegments) {
  const std::vector<Point> points = {{-0.0, 0.0}, {0.0, -0.0}, {-0.0, -0.0}, {3, 0},
                                     {-3, 0},     {0, 5},      {1e-300, 0},  {0, -1e300}};
  expect_row_matches(points, Point(-0.0, 0.0), Point(2.0, 0.0));
  expect_row_matches(points, Point(0.0, 0.0), Point(0.0, -0.0));
  expect_row_matches(points, Point(0.0, 4.0), Point(-0.0, -4.0));
  expect_row_matches(points, Point(1e-170, 0.0), Point(0.0, 1e-170));  // length_sq underflows
}

}  // namespace
}  // namespace scbt
