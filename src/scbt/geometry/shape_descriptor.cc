#include "scbt/geometry/shape_descriptor.h"

#include <cmath>
#include <limits>
#include <vector>

#include "scbt/geometry/avx2_clones.h"

namespace scbt {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kN = ShapeDescriptor::kSamples;
constexpr int kK = ShapeDescriptor::kHarmonics;

// cos and sin of 2 pi k i / N for harmonics k = 1..kK, computed once, indexed [i][k - 1] so that
// the sums over i run for all harmonics at once.
struct Twiddles {
  double cos_table[kN][kK];
  double sin_table[kN][kK];
  Twiddles() {
    for (int i = 0; i < kN; ++i) {
      for (int k = 1; k <= kK; ++k) {
        const int phase = (k * i) % kN;
        cos_table[i][k - 1] = std::cos(2.0 * kPi * phase / kN);
        sin_table[i][k - 1] = std::sin(2.0 * kPi * phase / kN);
      }
    }
  }
};

// The real and imaginary parts of r's DFT at harmonics 1..kK. Each harmonic's sums are taken over
// i in order, all harmonics side by side: independent sums the compiler puts in vector lanes (four
// wide in the AVX2 clone), the same additions in the same order as one harmonic at a time.
SCBT_AVX2_CLONES void harmonic_sums(const double* r, const Twiddles& twiddles, double* re_out,
                                    double* im_out) {
  double re[kK] = {}, im[kK] = {};  // local: kept in registers
  for (int i = 0; i < kN; ++i) {
    for (int k = 0; k < kK; ++k) {
      re[k] += r[i] * twiddles.cos_table[i][k];
      im[k] -= r[i] * twiddles.sin_table[i][k];
    }
  }
  for (int k = 0; k < kK; ++k) {
    re_out[k] = re[k];
    im_out[k] = im[k];
  }
}

// The descriptor of the closed polygon p[0..n). One pass takes the sums of area(), perimeter() and
// centroid() (each added in their order, so each equals theirs to the bit) and keeps the edge
// lengths for the sampling.
ShapeDescriptor describe(const Point* p, size_t n) {
  ShapeDescriptor descriptor;
  if (n < 3) return descriptor;
  // lengths[e]: |p[e + 1] - p[e]| (edge n - 1 closing at p[0]); norm(a - b) == norm(b - a). Kept
  // between calls.
  thread_local std::vector<double> lengths;
  lengths.resize(n);
  double* const edge_lengths = lengths.data();
  double twice_area = 0.0, length = 0.0, cx = 0.0, cy = 0.0;
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const double cross = p[j].x * p[i].y - p[i].x * p[j].y;
    twice_area += cross;
    cx += (p[j].x + p[i].x) * cross;
    cy += (p[j].y + p[i].y) * cross;
    const double edge = cv::norm(p[i] - p[j]);
    edge_lengths[j] = edge;
    length += edge;
  }
  const double signed_area = 0.5 * twice_area;
  if (!(std::abs(signed_area) > 0.0)) return descriptor;
  if (!(length > 0.0) || !std::isfinite(length)) return descriptor;
  Point center;
  if (std::abs(signed_area) < 1e-12) {
    for (size_t i = 0; i < n; ++i) center += p[i];
    center *= 1.0 / static_cast<double>(n);
  } else {
    center = Point(cx / (6.0 * signed_area), cy / (6.0 * signed_area));
  }

  // r at kN points equally spaced along the boundary, starting at vertex 0: the offsets from the
  // centre first, then their lengths (a loop of square roots alone, which vectorises).
  double dx[kN], dy[kN];
  const double step = length / kN;
  size_t edge = 0;
  double edge_start = 0.0;  // arc length at p[edge]
  double edge_length = edge_lengths[0];
  for (int i = 0; i < kN; ++i) {
    const double s = i * step;
    while (s > edge_start + edge_length && edge + 1 < n) {
      edge_start += edge_length;
      ++edge;
      edge_length = edge_lengths[edge];
    }
    const double t = edge_length > 0.0 ? std::min(1.0, (s - edge_start) / edge_length) : 0.0;
    const Point a = p[edge], b = p[edge + 1 < n ? edge + 1 : 0];
    const Point d = a + t * (b - a) - center;
    dx[i] = d.x;
    dy[i] = d.y;
  }
  double r[kN];
  for (int i = 0; i < kN; ++i) r[i] = std::sqrt(dx[i] * dx[i] + dy[i] * dy[i]);
  double mean = 0.0;
  for (double v : r) mean += v;
  mean /= kN;
  if (!(mean > 0.0)) return descriptor;

  static const Twiddles twiddles;
  double re[kK], im[kK];
  harmonic_sums(r, twiddles, re, im);
  for (int k = 0; k < kK; ++k) descriptor.magnitudes[k] = std::hypot(re[k], im[k]) / (kN * mean);
  descriptor.valid = true;
  return descriptor;
}

}  // namespace

ShapeDescriptor shape_descriptor(const Polygon& polygon) {
  return describe(polygon.data(), polygon.size());
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

ShapeDescriptor affine_shape_descriptor(const Polygon& polygon, double* aspect) {
  if (aspect) *aspect = std::numeric_limits<double>::infinity();
  const size_t n = polygon.size();
  if (n < 3) return ShapeDescriptor();
  // Second moments of the region by Green's theorem, about the first vertex (for precision).
  // Each edge's end is the next one's start: its offset and its own products (the same
  // expressions) are carried over rather than computed again.
  double a2 = 0.0, cx = 0.0, cy = 0.0, xx = 0.0, yy = 0.0, xy = 0.0;
  Point p = polygon[0] - polygon[0];  // not (0, 0) for a non-finite vertex
  double p_xx = p.x * p.x, p_yy = p.y * p.y, p_xy2 = 2.0 * p.x * p.y;
  for (size_t i = 0; i < n; ++i) {
    const Point q = polygon[i + 1 < n ? i + 1 : 0] - polygon[0];
    const double q_xx = q.x * q.x, q_yy = q.y * q.y, q_xy2 = 2.0 * q.x * q.y;
    const double cross = p.x * q.y - q.x * p.y;
    a2 += cross;
    cx += (p.x + q.x) * cross;
    cy += (p.y + q.y) * cross;
    xx += (p_xx + p.x * q.x + q_xx) * cross;
    yy += (p_yy + p.y * q.y + q_yy) * cross;
    xy += (p.x * q.y + p_xy2 + q_xy2 + q.x * p.y) * cross;
    p = q;
    p_xx = q_xx;
    p_yy = q_yy;
    p_xy2 = q_xy2;
  }
  if (!(std::abs(a2) > 0.0) || !std::isfinite(a2)) return ShapeDescriptor();
  cx /= 3.0 * a2;
  cy /= 3.0 * a2;
  // Central moments over the area (signs cancel with the orientation's).
  const double sxx = xx / (6.0 * a2) - cx * cx;
  const double syy = yy / (6.0 * a2) - cy * cy;
  const double sxy = xy / (12.0 * a2) - cx * cy;
  const double half_sum = 0.5 * (sxx + syy);
  const double root = std::hypot(0.5 * (sxx - syy), sxy);
  const double major = half_sum + root, minor = half_sum - root;
  if (!(minor > 0.0) || !std::isfinite(major)) return ShapeDescriptor();
  // Rotate the major axis onto x and divide each axis by its spread: the whitened polygon. (The
  // rotation left over is what the descriptor ignores anyway.)
  const double angle = 0.5 * std::atan2(2.0 * sxy, sxx - syy);
  const double c = std::cos(angle), s = std::sin(angle);
  const double kx = 1.0 / std::sqrt(major), ky = 1.0 / std::sqrt(minor);
  // Kept between calls: the choice whitens several cycles a frame.
  thread_local Polygon whitened;
  whitened.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const Point d = polygon[i] - polygon[0] - Point(cx, cy);
    whitened[i] = Point(kx * (c * d.x + s * d.y), ky * (-s * d.x + c * d.y));
  }
  if (aspect) *aspect = std::sqrt(major / minor);
  return describe(whitened.data(), n);
}

}  // namespace scbt
