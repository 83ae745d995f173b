#include "scbt/depth/boundary_samples.h"

#include <cmath>

namespace scbt {
namespace {

// The unit normal of edge a->b on the interior's side: the left of the edge when the shoelace
// sum is positive (the formula is orientation-algebraic, so it holds in image coordinates too).
Point inward_normal(const Point& a, const Point& b, double orientation) {
  const Point d = b - a;
  const double length = std::hypot(d.x, d.y);
  return Point(-d.y, d.x) * (orientation / length);
}

}  // namespace

std::vector<BoundarySample> sample_boundary_inward(const Polygon& polygon, double step) {
  Polygon vertices;
  vertices.reserve(polygon.size());
  for (const Point& p : polygon)
    if (vertices.empty() || p != vertices.back()) vertices.push_back(p);
  while (vertices.size() > 1 && vertices.front() == vertices.back()) vertices.pop_back();
  std::vector<BoundarySample> samples;
  const double shoelace = signed_area(vertices);
  if (vertices.size() < 3 || shoelace == 0.0) return samples;
  const double orientation = shoelace > 0.0 ? 1.0 : -1.0;
  const std::size_t n = vertices.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point& a = vertices[i];
    const Point& b = vertices[(i + 1) % n];
    const Point& before = vertices[(i + n - 1) % n];
    const Point edge_normal = inward_normal(a, b, orientation);
    Point bisector = inward_normal(before, a, orientation) + edge_normal;
    const double bisector_length = std::hypot(bisector.x, bisector.y);
    bisector = bisector_length > 1e-9 ? bisector / bisector_length : edge_normal;
    samples.push_back({a, bisector, true});
    const int pieces = static_cast<int>(std::ceil(std::hypot(b.x - a.x, b.y - a.y) / step));
    for (int k = 1; k < pieces; ++k)
      samples.push_back({a + (b - a) * (static_cast<double>(k) / pieces), edge_normal, false});
  }
  return samples;
}

}  // namespace scbt
