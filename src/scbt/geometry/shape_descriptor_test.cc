// Properties of the centroid-distance Fourier descriptor over random star-shaped polygons.
#include "scbt/geometry/shape_descriptor.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace scbt {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The 5th percentile of the distances between descriptors 0-1, 2-3, ... (unrelated random shapes).
double unrelated_fifth_percentile(const std::vector<ShapeDescriptor>& descriptors) {
  std::vector<double> unrelated;
  for (size_t i = 0; i + 1 < descriptors.size(); i += 2) {
    unrelated.push_back(shape_distance(descriptors[i], descriptors[i + 1]));
  }
  std::sort(unrelated.begin(), unrelated.end());
  return unrelated[unrelated.size() / 20];
}

// A star-shaped polygon around the origin: n vertices at increasing angles with random radii.
Polygon random_star(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> radius(40.0, 100.0), jitter(0.1, 0.9);
  Polygon polygon;
  for (int i = 0; i < n; ++i) {
    const double angle = 2.0 * kPi * (i + jitter(rng)) / n;
    const double r = radius(rng);
    polygon.emplace_back(r * std::cos(angle), r * std::sin(angle));
  }
  return polygon;
}

Polygon ellipse(double a, double b, int n) {
  Polygon polygon;
  for (int i = 0; i < n; ++i) {
    const double t = 2.0 * kPi * i / n;
    polygon.emplace_back(a * std::cos(t), b * std::sin(t));
  }
  return polygon;
}

// Rotation by `angle`, scale, translation, then the vertex list rotated by `first` positions and
// reversed when `reverse`: the same closed shape, described differently.
Polygon transformed(const Polygon& polygon, double angle, double scale, Point shift, int first,
                    bool reverse) {
  Polygon out;
  const double c = std::cos(angle), s = std::sin(angle);
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Point& p = polygon[(i + first) % polygon.size()];
    out.push_back(Point(c * p.x - s * p.y, s * p.x + c * p.y) * scale + shift);
  }
  if (reverse) std::reverse(out.begin(), out.end());
  return out;
}

// A polygon's edges split into short pieces: the same outline with many more vertices, as a
// tracked cycle of short segments has.
Polygon subdivided(const Polygon& polygon, double max_piece) {
  Polygon out;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Point& a = polygon[i];
    const Point& b = polygon[(i + 1) % polygon.size()];
    const int pieces = std::max(1, static_cast<int>(std::ceil(cv::norm(b - a) / max_piece)));
    for (int k = 0; k < pieces; ++k) out.push_back(a + (b - a) * (static_cast<double>(k) / pieces));
  }
  return out;
}

TEST(ShapeDescriptorTest, InvalidForDegeneratePolygons) {
  EXPECT_FALSE(shape_descriptor({}).valid);
  EXPECT_FALSE(shape_descriptor({{0, 0}, {1, 1}}).valid);
  EXPECT_FALSE(shape_descriptor({{0, 0}, {1, 1}, {2, 2}}).valid);
  EXPECT_TRUE(
      std::isinf(shape_distance(shape_descriptor({}), shape_descriptor(ellipse(2, 1, 40)))));
}

TEST(ShapeDescriptorTest, CircleIsNearZeroAndEllipsesGrowWithElongation) {
  const ShapeDescriptor circle = shape_descriptor(ellipse(50, 50, 200));
  ASSERT_TRUE(circle.valid);
  for (double m : circle.magnitudes) EXPECT_LT(m, 1e-3);
  double previous = 0.0;
  for (double aspect : {1.2, 1.5, 2.0, 3.0}) {
    const double d = shape_distance(circle, shape_descriptor(ellipse(50 * aspect, 50, 200)));
    EXPECT_GT(d, previous) << "aspect " << aspect;
    previous = d;
  }
}

// Translation, rotation, scale 0.6-1.6, another starting vertex and the other direction move the
// descriptor by far less than the distance between two unrelated random shapes.
TEST(ShapeDescriptorTest, InvariantToSimilarityAndVertexOrderOverRandomShapes) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(-kPi, kPi), scale(0.6, 1.6), shift(-500.0, 500.0);
  std::uniform_int_distribution<int> vertices(5, 12);
  std::vector<ShapeDescriptor> descriptors;
  double worst_invariance = 0.0;
  for (int trial = 0; trial < 200; ++trial) {
    const Polygon shape = random_star(rng, vertices(rng));
    const ShapeDescriptor d = shape_descriptor(shape);
    ASSERT_TRUE(d.valid);
    const Polygon moved = transformed(shape, angle(rng), scale(rng), Point(shift(rng), shift(rng)),
                                      trial % static_cast<int>(shape.size()), trial % 2 == 1);
    const double invariance = shape_distance(d, shape_descriptor(moved));
    worst_invariance = std::max(worst_invariance, invariance);
    // The same outline cut into 3-px pieces (a tracked cycle's many vertices).
    EXPECT_LT(shape_distance(d, shape_descriptor(subdivided(moved, 3.0))), 0.02) << trial;
    descriptors.push_back(d);
  }
  EXPECT_LT(worst_invariance, 0.02);
  // Nearly every pair of unrelated random shapes is further apart than any transformed copy.
  const double fifth_percentile = unrelated_fifth_percentile(descriptors);
  EXPECT_GT(fifth_percentile, 2.0 * worst_invariance)
      << "5th percentile " << fifth_percentile << ", worst invariance " << worst_invariance;
}

// Vertex noise of a pixel on an object of radius 40-100 px changes the descriptor little.
TEST(ShapeDescriptorTest, StableUnderOnePixelVertexNoise) {
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0.0, 1.0);
  for (int trial = 0; trial < 100; ++trial) {
    const Polygon shape = subdivided(random_star(rng, 7), 5.0);
    Polygon noisy = shape;
    for (Point& p : noisy) p += Point(noise(rng), noise(rng));
    EXPECT_LT(shape_distance(shape_descriptor(shape), shape_descriptor(noisy)), 0.05) << trial;
  }
}

// The affine-normalised descriptor: every ellipse is a circle, the axis ratio is reported.
TEST(AffineShapeDescriptorTest, EllipsesAreOneShapeAndTheirAspectIsMeasured) {
  const ShapeDescriptor circle = affine_shape_descriptor(ellipse(50, 50, 200));
  for (double aspect : {1.0, 1.5, 3.0}) {
    double measured = 0.0;
    const ShapeDescriptor d = affine_shape_descriptor(ellipse(40 * aspect, 40, 200), &measured);
    ASSERT_TRUE(d.valid);
    EXPECT_LT(shape_distance(circle, d), 1e-3) << aspect;
    EXPECT_NEAR(measured, aspect, 1e-3 * aspect);
  }
  double aspect = 0.0;
  EXPECT_FALSE(affine_shape_descriptor({{0, 0}, {1, 1}, {2, 2}}, &aspect).valid);
  EXPECT_TRUE(std::isinf(aspect));
}

// Random affine maps (stretch up to 2:1 in any direction, shear, rotation, translation) move the
// affine descriptor by far less than the distance between unrelated random shapes.
TEST(AffineShapeDescriptorTest, InvariantToAffineMapsOverRandomShapes) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> angle(-kPi, kPi), stretch(1.0, 2.0), shear(-0.3, 0.3),
      shift(-500.0, 500.0);
  std::uniform_int_distribution<int> vertices(5, 12);
  std::vector<ShapeDescriptor> descriptors;
  double worst_invariance = 0.0;
  for (int trial = 0; trial < 200; ++trial) {
    const Polygon shape = random_star(rng, vertices(rng));
    const ShapeDescriptor d = affine_shape_descriptor(shape);
    ASSERT_TRUE(d.valid);
    // Stretch along a random direction, shear, then a similarity and another vertex order.
    const double t = angle(rng), k = stretch(rng), h = shear(rng);
    Polygon mapped;
    for (const Point& p : shape) {
      const Point r(std::cos(t) * p.x + std::sin(t) * p.y, -std::sin(t) * p.x + std::cos(t) * p.y);
      const Point stretched(k * r.x + h * r.y, r.y);
      mapped.emplace_back(std::cos(t) * stretched.x - std::sin(t) * stretched.y,
                          std::sin(t) * stretched.x + std::cos(t) * stretched.y);
    }
    mapped = transformed(subdivided(mapped, 3.0), angle(rng), 1.0, Point(shift(rng), shift(rng)),
                         trial, trial % 2 == 1);
    worst_invariance =
        std::max(worst_invariance, shape_distance(d, affine_shape_descriptor(mapped)));
    descriptors.push_back(d);
  }
  EXPECT_LT(worst_invariance, 0.03);
  const double fifth_percentile = unrelated_fifth_percentile(descriptors);
  EXPECT_GT(fifth_percentile, 2.0 * worst_invariance)
      << "5th percentile " << fifth_percentile << ", worst invariance " << worst_invariance;
}

}  // namespace
}  // namespace scbt
