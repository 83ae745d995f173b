#include "scbt/geometry/shape_descriptor.h"

#include <cmath>
#include <limits>

namespace scbt {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kN = ShapeDescriptor::kSamples;
constexpr int kK = ShapeDescriptor::kHarmonics;

// cos and sin of 2 pi k i / N, computed once.
struct Twiddles {
  double cos_table[kN];
  double sin_table[kN];
  Twiddles() {
    for (int i = 0; i < kN; ++i) {
      cos_table[i] = std::cos(2.0 * kPi * i / kN);
      sin_table[i] = std::sin(2.0 * kPi * i / kN);
    }
  }
};

}  // namespace

ShapeDescriptor shape_descriptor(const Polygon& polygon) {
  ShapeDescriptor descriptor;
  const size_t n = polygon.size();
  if (n < 3 || !(area(polygon) > 0.0)) return descriptor;
  const double length = perimeter(polygon);
  if (!(length > 0.0) || !std::isfinite(length)) return descriptor;
  const Point center = centroid(polygon);

  // r at kN points equally spaced along the boundary, starting at vertex 0.
  double r[kN];
  const double step = length / kN;
  size_t edge = 0;
  double edge_start = 0.0;  // arc length at polygon[edge]
  double edge_length = cv::norm(polygon[1] - polygon[0]);
  for (int i = 0; i < kN; ++i) {
    const double s = i * step;
    while (s > edge_start + edge_length && edge + 1 < n) {
      edge_start += edge_length;
      ++edge;
      edge_length = cv::norm(polygon[(edge + 1) % n] - polygon[edge]);
    }
    const double t = edge_length > 0.0 ? std::min(1.0, (s - edge_start) / edge_length) : 0.0;
    const Point p = polygon[edge] + t * (polygon[(edge + 1) % n] - polygon[edge]);
    r[i] = cv::norm(p - center);
  }
  double mean = 0.0;
  for (double v : r) mean += v;
  mean /= kN;
  if (!(mean > 0.0)) return descriptor;

  static const Twiddles twiddles;
  for (int k = 1; k <= kK; ++k) {
    double re = 0.0, im = 0.0;
    for (int i = 0; i < kN; ++i) {
      const int phase = (k * i) % kN;
      re += r[i] * twiddles.cos_table[phase];
      im -= r[i] * twiddles.sin_table[phase];
    }
    descriptor.magnitudes[k - 1] = std::hypot(re, im) / (kN * mean);
  }
  descriptor.valid = true;
  return descriptor;
}

double shape_distance(const ShapeDescriptor& a, const ShapeDescriptor& b) {
  if (!a.valid || !b.valid) return std::numeric_limits<double>::infinity();
  double sum = 0.0;
  for (int k = 0; k < kK; ++k) {
    const double d = a.magnitudes[k] - b.magnitudes[k];
    sum += d * d;
  }
  return std::sqrt(sum);
}

}  // namespace scbt
