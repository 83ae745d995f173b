#include "scbt/depth/boundary_samples.h"

#include <algorithm>
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

// The part of the segment a + t (b - a), t in [0, 1], inside `region` (Liang-Barsky), as
// [*t0, *t1]; false when none of it is.
bool clip_to_region(const Point& a, const Point& b, const SampleRegion& region, double* t0,
                    double* t1) {
  const Point d = b - a;
  const double p[4] = {-d.x, d.x, -d.y, d.y};
  const double q[4] = {a.x - region.x_min, region.x_max - a.x, a.y - region.y_min,
                       region.y_max - a.y};
  *t0 = 0.0;
  *t1 = 1.0;
  for (int k = 0; k < 4; ++k) {
    if (p[k] == 0.0) {
      if (q[k] < 0.0) return false;  // parallel to this side, and outside it
      continue;
    }
    const double t = q[k] / p[k];
    if (p[k] < 0.0)
      *t0 = std::max(*t0, t);
    else
      *t1 = std::min(*t1, t);
  }
  return *t0 <= *t1;  // false for NaN too
}

// The points along edge a->b inside `region`, as parameters t of a + t (b - a), in order. They
// are those of the edge cut into ceil(length / step) equal pieces (the same with or without a
// region); for an edge too long for that grid in a double, the part inside cut on its own.
void points_along(const Point& a, const Point& b, double step, const SampleRegion& region,
                  std::vector<double>* out) {
  out->clear();
  double t0 = 0.0, t1 = 0.0;
  if (!clip_to_region(a, b, region, &t0, &t1)) return;
  const double length = std::hypot(b.x - a.x, b.y - a.y);
  const double pieces = std::ceil(length / step);
  if (!(pieces < 0x1p52)) {
    const double inside = std::ceil((t1 - t0) * length / step);
    if (!(inside >= 1.0 && inside < 0x1p52)) return;
    for (double k = 0.0; k <= inside; k += 1.0) {
      const double t = t0 + (t1 - t0) * (k / inside);
      if (t > 0.0 && t < 1.0) out->push_back(t);  // not a vertex
    }
    return;
  }
  const double first = std::max(1.0, std::ceil(t0 * pieces));
  const double last = std::min(pieces - 1.0, std::floor(t1 * pieces));
  for (double k = first; k <= last; k += 1.0) out->push_back(k / pieces);
}

}  // namespace

std::vector<BoundarySample> sample_boundary_inward(const Polygon& polygon, double step,
                                                   const SampleRegion& region,
                                                   std::size_t max_edge_samples) {
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
  // More points along the edges inside the region than max_edge_samples: a longer step.
  double inside_length = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Point& a = vertices[i];
    const Point& b = vertices[(i + 1) % n];
    double t0 = 0.0, t1 = 0.0;
    if (clip_to_region(a, b, region, &t0, &t1))
      inside_length += (t1 - t0) * std::hypot(b.x - a.x, b.y - a.y);
  }
  const double most = static_cast<double>(std::max<std::size_t>(max_edge_samples, 1));
  if (inside_length / step > most) step = inside_length / most;
  std::vector<double> along;
  for (std::size_t i = 0; i < n; ++i) {
    const Point& a = vertices[i];
    const Point& b = vertices[(i + 1) % n];
    const Point& before = vertices[(i + n - 1) % n];
    const Point edge_normal = inward_normal(a, b, orientation);
    Point bisector = inward_normal(before, a, orientation) + edge_normal;
    const double bisector_length = std::hypot(bisector.x, bisector.y);
    bisector = bisector_length > 1e-9 ? bisector / bisector_length : edge_normal;
    samples.push_back({a, bisector, true});
    points_along(a, b, step, region, &along);
    for (double t : along) samples.push_back({a + (b - a) * t, edge_normal, false});
  }
  return samples;
}

}  // namespace scbt
