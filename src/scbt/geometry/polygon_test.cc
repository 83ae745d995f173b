// Property tests of the polygon measures over many seeded random polygons.
#include "scbt/geometry/polygon.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace scbt {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A star-shaped polygon around `center`: n vertices at increasing angles with random radii.
// Counter-clockwise in a y-up frame (positive signed area).
Polygon random_star(std::mt19937& rng, Point center, int n, double min_radius, double max_radius) {
  std::uniform_real_distribution<double> radius(min_radius, max_radius), jitter(0.1, 0.9);
  Polygon polygon;
  for (int i = 0; i < n; ++i) {
    const double angle = 2.0 * kPi * (i + jitter(rng)) / n;
    const double r = radius(rng);
    polygon.emplace_back(center.x + r * std::cos(angle), center.y + r * std::sin(angle));
  }
  return polygon;
}

// A convex polygon: random angles on an ellipse, sorted.
Polygon random_convex(std::mt19937& rng, Point center, int n) {
  std::uniform_real_distribution<double> angle(0.0, 2.0 * kPi), axis(20.0, 120.0);
  std::vector<double> angles(n);
  for (double& a : angles) a = angle(rng);
  std::sort(angles.begin(), angles.end());
  const double rx = axis(rng), ry = axis(rng);
  Polygon polygon;
  for (double a : angles)
    polygon.emplace_back(center.x + rx * std::cos(a), center.y + ry * std::sin(a));
  return polygon;
}

struct Rigid {
  double angle;
  Point translation;
  Point apply(const Point& p) const {
    const double c = std::cos(angle), s = std::sin(angle);
    return {c * p.x - s * p.y + translation.x, s * p.x + c * p.y + translation.y};
  }
};

Polygon transform(const Polygon& polygon, const Rigid& motion) {
  Polygon out;
  for (const Point& p : polygon) out.push_back(motion.apply(p));
  return out;
}

Polygon scaled(const Polygon& polygon, double s) {
  Polygon out;
  for (const Point& p : polygon) out.push_back(p * s);
  return out;
}

Rigid random_rigid(std::mt19937& rng) {
  std::uniform_real_distribution<double> angle(-kPi, kPi), shift(-500.0, 500.0);
  return {angle(rng), Point(shift(rng), shift(rng))};
}

class PolygonProperty : public ::testing::TestWithParam<unsigned> {
 protected:
  std::mt19937 rng{GetParam() * 2654435761u + 17u};
  Polygon make_polygon() {
    std::uniform_int_distribution<int> count(3, 24);
    std::uniform_real_distribution<double> pos(-200.0, 200.0);
    return random_star(rng, Point(pos(rng), pos(rng)), count(rng), 5.0, 150.0);
  }
};

TEST_P(PolygonProperty, AreaAndOrientationInvariantUnderRigidMotion) {
  const Polygon polygon = make_polygon();
  const Rigid motion = random_rigid(rng);
  const Polygon moved = transform(polygon, motion);
  const double a = signed_area(polygon);
  const double b = signed_area(moved);
  ASSERT_GT(a, 0.0);  // built counter-clockwise
  EXPECT_NEAR(a, b, 1e-9 * std::max(1.0, std::abs(a)) + 1e-6);
  EXPECT_GT(b, 0.0);
  EXPECT_NEAR(area(polygon), area(moved), 1e-6);

  // Reversing the vertex order flips the sign only.
  Polygon reversed(polygon.rbegin(), polygon.rend());
  EXPECT_NEAR(signed_area(reversed), -a, 1e-9 * std::abs(a));
  EXPECT_DOUBLE_EQ(area(reversed), area(polygon));

  // A reflection (mirror x) flips the orientation.
  Polygon mirrored;
  for (const Point& p : polygon) mirrored.emplace_back(-p.x, p.y);
  EXPECT_LT(signed_area(mirrored), 0.0);
}

TEST_P(PolygonProperty, AreaScalesWithSquareOfScale) {
  const Polygon polygon = make_polygon();
  std::uniform_real_distribution<double> scale(0.1, 10.0);
  const double s = scale(rng);
  EXPECT_NEAR(signed_area(scaled(polygon, s)), s * s * signed_area(polygon),
              1e-9 * s * s * area(polygon));
  EXPECT_NEAR(perimeter(scaled(polygon, s)), s * perimeter(polygon), 1e-9 * s * perimeter(polygon));
  // A negative scale is a rotation by pi: same orientation.
  EXPECT_NEAR(signed_area(scaled(polygon, -s)), s * s * signed_area(polygon),
              1e-9 * s * s * area(polygon));
}

TEST_P(PolygonProperty, PerimeterInvariantUnderRigidMotionAndMatchesEdgeSum) {
  const Polygon polygon = make_polygon();
  const Polygon moved = transform(polygon, random_rigid(rng));
  double edges = 0.0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Point d = polygon[(i + 1) % polygon.size()] - polygon[i];
    edges += std::sqrt(d.x * d.x + d.y * d.y);
  }
  EXPECT_NEAR(perimeter(polygon), edges, 1e-9 * edges);
  EXPECT_NEAR(perimeter(moved), edges, 1e-9 * edges);
}

TEST_P(PolygonProperty, DistanceToBoundaryMatchesDenseSampling) {
  const Polygon polygon = make_polygon();
  // Dense samples on every edge, spacing at most `step`.
  const double step = 0.05;
  std::vector<Point> samples;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Point a = polygon[i];
    const Point b = polygon[(i + 1) % polygon.size()];
    const int k = std::max(1, static_cast<int>(std::ceil(cv::norm(b - a) / step)));
    for (int t = 0; t <= k; ++t) samples.push_back(a + (b - a) * (static_cast<double>(t) / k));
  }
  const cv::Rect2d box = bounding_box(polygon);
  std::uniform_real_distribution<double> px(box.x - 50.0, box.x + box.width + 50.0);
  std::uniform_real_distribution<double> py(box.y - 50.0, box.y + box.height + 50.0);
  for (int q = 0; q < 10; ++q) {
    const Point p(px(rng), py(rng));
    double brute = std::numeric_limits<double>::infinity();
    for (const Point& s : samples) brute = std::min(brute, cv::norm(p - s));
    const double d = distance_to_boundary(p, polygon);
    // The exact distance is never above a sample's, and at most half a step below the nearest.
    EXPECT_LE(d, brute + 1e-9);
    EXPECT_GE(d, brute - step);
  }
  // Vertices and edge midpoints are on the boundary.
  EXPECT_NEAR(distance_to_boundary(polygon[0], polygon), 0.0, 1e-9);
  EXPECT_NEAR(distance_to_boundary((polygon[0] + polygon[1]) * 0.5, polygon), 0.0, 1e-9);
}

TEST_P(PolygonProperty, StarShapedAndConvexPolygonsAreSimple) {
  EXPECT_TRUE(is_simple(make_polygon()));
  std::uniform_int_distribution<int> count(3, 30);
  const Polygon convex = random_convex(rng, Point(100.0, 100.0), count(rng));
  if (count_distinct_points(convex) == static_cast<int>(convex.size())) {
    EXPECT_TRUE(is_simple(convex));
  }
}

TEST_P(PolygonProperty, CentroidMovesWithTranslation) {
  const Polygon polygon = make_polygon();
  std::uniform_real_distribution<double> shift(-300.0, 300.0);
  const Point t(shift(rng), shift(rng));
  Polygon moved;
  for (const Point& p : polygon) moved.push_back(p + t);
  const Point c = centroid(polygon);
  const Point c2 = centroid(moved);
  EXPECT_NEAR(c2.x - c.x, t.x, 1e-6);
  EXPECT_NEAR(c2.y - c.y, t.y, 1e-6);
  // The centroid of a convex polygon lies inside its bounding box.
  const Polygon convex = random_convex(rng, Point(0.0, 0.0), 12);
  const Point cc = centroid(convex);
  const cv::Rect2d box = bounding_box(convex);
  EXPECT_GE(cc.x, box.x);
  EXPECT_LE(cc.x, box.x + box.width);
  EXPECT_GE(cc.y, box.y);
  EXPECT_LE(cc.y, box.y + box.height);
}

TEST_P(PolygonProperty, CountDistinctPointsIgnoresRepeats) {
  const Polygon polygon = make_polygon();
  Polygon with_repeats = polygon;
  std::uniform_int_distribution<size_t> pick(0, polygon.size() - 1);
  const int repeats = 1 + static_cast<int>(pick(rng) % 5);
  for (int i = 0; i < repeats; ++i) with_repeats.push_back(polygon[pick(rng)]);
  std::shuffle(with_repeats.begin(), with_repeats.end(), rng);
  EXPECT_EQ(count_distinct_points(polygon), static_cast<int>(polygon.size()));
  EXPECT_EQ(count_distinct_points(with_repeats), static_cast<int>(polygon.size()));
}

INSTANTIATE_TEST_SUITE_P(Seeds, PolygonProperty, ::testing::Range(0u, 100u));

TEST(Polygon, UnitSquareMeasures) {
  const Polygon square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_DOUBLE_EQ(signed_area(square), 1.0);
  EXPECT_DOUBLE_EQ(perimeter(square), 4.0);
  const Point c = centroid(square);
  EXPECT_DOUBLE_EQ(c.x, 0.5);
  EXPECT_DOUBLE_EQ(c.y, 0.5);
  EXPECT_DOUBLE_EQ(distance_to_boundary({0.5, 0.5}, square), 0.5);
  EXPECT_DOUBLE_EQ(distance_to_boundary({3.0, 1.0}, square), 2.0);
  const cv::Rect2d box = bounding_box(square);
  EXPECT_DOUBLE_EQ(box.width, 1.0);
  EXPECT_DOUBLE_EQ(box.height, 1.0);
}

TEST(Polygon, DegenerateInputs) {
  EXPECT_EQ(signed_area({}), 0.0);
  EXPECT_EQ(signed_area({{1, 1}, {2, 2}}), 0.0);
  EXPECT_EQ(perimeter({{1, 1}}), 0.0);
  EXPECT_TRUE(std::isinf(distance_to_boundary({0, 0}, {})));
  EXPECT_DOUBLE_EQ(distance_to_boundary({3, 4}, {{0, 0}}), 5.0);
  EXPECT_DOUBLE_EQ(distance_to_segment({3, 4}, {0, 0}, {0, 0}), 5.0);
  EXPECT_FALSE(is_simple({{0, 0}, {1, 0}}));
  EXPECT_EQ(count_distinct_points({}), 0);
  // Collinear vertices: no area, centroid falls back to the vertex mean.
  const Point c = centroid({{0, 0}, {2, 0}, {4, 0}});
  EXPECT_DOUBLE_EQ(c.x, 2.0);
  EXPECT_DOUBLE_EQ(c.y, 0.0);
}

TEST(Polygon, BowTieIsNotSimple) {
  EXPECT_FALSE(is_simple({{0, 0}, {10, 10}, {10, 0}, {0, 10}}));
  // The same four points in order are simple.
  EXPECT_TRUE(is_simple({{0, 0}, {10, 0}, {10, 10}, {0, 10}}));
  // A spike folding back onto the previous edge is not simple.
  EXPECT_FALSE(is_simple({{0, 0}, {10, 0}, {5, 0}, {5, 5}}));
  // Non-adjacent edges touching at a vertex is not simple.
  EXPECT_FALSE(is_simple({{0, 0}, {10, 0}, {5, 5}, {10, 10}, {0, 10}, {5, 5}}));
}

// The sweep in is_simple against every pair of edges, on random polygons that are often not
// simple (random vertices, some on a coarse grid so that edges touch and overlap).
bool is_simple_by_all_pairs(const Polygon& polygon) {
  const size_t n = polygon.size();
  if (n < 3) return false;
  auto orientation = [](const Point& p, const Point& q, const Point& r) {
    const double cross = (q - p).cross(r - p);
    return cross > 0 ? 1 : (cross < 0 ? -1 : 0);
  };
  auto on_segment = [](const Point& p, const Point& a, const Point& b) {
    return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
           p.y <= std::max(a.y, b.y);
  };
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = i + 1; j < n; ++j) {
      const Point &a1 = polygon[i], &a2 = polygon[(i + 1) % n];
      const Point &b1 = polygon[j], &b2 = polygon[(j + 1) % n];
      if (j == i + 1 || (i == 0 && j == n - 1)) {
        const Point& shared = j == i + 1 ? a2 : a1;
        const Point& other_a = j == i + 1 ? a1 : a2;
        const Point& other_b = j == i + 1 ? b2 : b1;
        if (orientation(other_a, shared, other_b) == 0 &&
            (other_a - shared).dot(other_b - shared) > 0) {
          return false;
        }
        continue;
      }
      const int o1 = orientation(a1, a2, b1), o2 = orientation(a1, a2, b2);
      const int o3 = orientation(b1, b2, a1), o4 = orientation(b1, b2, a2);
      if ((o1 != o2 && o3 != o4) || (o1 == 0 && on_segment(b1, a1, a2)) ||
          (o2 == 0 && on_segment(b2, a1, a2)) || (o3 == 0 && on_segment(a1, b1, b2)) ||
          (o4 == 0 && on_segment(a2, b1, b2))) {
        return false;
      }
    }
  }
  return true;
}

TEST(Polygon, IsSimpleSweepAgreesWithAllPairs) {
  std::mt19937 rng(7);
  int simple = 0, not_simple = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const int n = 3 + trial % 9;
    Polygon polygon;
    if (trial % 3 == 0) {
      polygon = random_star(rng, {50, 50}, n, 10, 40);
    } else {
      std::uniform_int_distribution<int> grid(0, trial % 3 == 1 ? 4 : 100);
      for (int i = 0; i < n; ++i) polygon.emplace_back(grid(rng), grid(rng));
    }
    const bool expected = is_simple_by_all_pairs(polygon);
    ASSERT_EQ(is_simple(polygon), expected) << "trial " << trial;
    (expected ? simple : not_simple) += 1;
  }
  EXPECT_GT(simple, 500);  // both outcomes well represented
  EXPECT_GT(not_simple, 500);
}

TEST(Polygon, SegmentsCrossBasics) {
  EXPECT_TRUE(segments_cross({0, 0}, {10, 10}, {0, 10}, {10, 0}));
  // Disjoint.
  EXPECT_FALSE(segments_cross({0, 0}, {1, 1}, {5, 0}, {6, 1}));
  // Sharing an endpoint.
  EXPECT_FALSE(segments_cross({0, 0}, {10, 0}, {10, 0}, {10, 10}));
  // T junction: an endpoint on the other's interior.
  EXPECT_FALSE(segments_cross({0, 0}, {10, 0}, {5, 0}, {5, 10}));
  // Collinear overlap.
  EXPECT_FALSE(segments_cross({0, 0}, {10, 0}, {5, 0}, {15, 0}));
  // Parallel.
  EXPECT_FALSE(segments_cross({0, 0}, {10, 0}, {0, 1}, {10, 1}));
}

TEST(Polygon, SegmentsCrossSymmetricOnRandomSegments) {
  std::mt19937 rng(4242);
  std::uniform_real_distribution<double> pos(0.0, 100.0);
  int crossings = 0;
  for (int i = 0; i < 500; ++i) {
    const Point p1(pos(rng), pos(rng)), p2(pos(rng), pos(rng)), q1(pos(rng), pos(rng)),
        q2(pos(rng), pos(rng));
    const bool c = segments_cross(p1, p2, q1, q2);
    EXPECT_EQ(c, segments_cross(q1, q2, p1, p2));
    EXPECT_EQ(c, segments_cross(p2, p1, q2, q1));
    // Independent check: solve p1 + s (p2 - p1) = q1 + t (q2 - q1) for s, t in (0, 1).
    const Point r = p2 - p1, d = q2 - q1, w = q1 - p1;
    const double denom = r.x * d.y - r.y * d.x;
    ASSERT_NE(denom, 0.0);
    const double s = (w.x * d.y - w.y * d.x) / denom;
    const double t = (w.x * r.y - w.y * r.x) / denom;
    EXPECT_EQ(c, s > 0.0 && s < 1.0 && t > 0.0 && t < 1.0);
    crossings += c;
  }
  EXPECT_GT(crossings, 20);  // the sample exercises both outcomes
  EXPECT_LT(crossings, 480);
}

}  // namespace
}  // namespace scbt
