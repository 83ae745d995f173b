#include "scbt/lines/band_mask.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace scbt {
namespace {

// The columns x of row y where a linear constraint low <= k x + m0 + m1 y <= high holds, as
// x in [from0 + from1 y, to0 + to1 y] (precomputed per edge so that a row costs no division),
// or, when k is 0, all columns or none depending on the row.
struct RowConstraint {
  bool depends_on_x = false;
  double from0 = 0.0, from1 = 0.0, to0 = 0.0, to1 = 0.0;
  double m0 = 0.0, m1 = 0.0, low = 0.0, high = 0.0;  // for k == 0

  RowConstraint(double k, double m0_, double m1_, double low_, double high_)
      : m0(m0_), m1(m1_), low(low_), high(high_) {
    if (std::abs(k) < 1e-12) return;
    depends_on_x = true;
    // (low - m0 - m1 y) / k and (high - m0 - m1 y) / k, in increasing order.
    from0 = (low - m0) / k, from1 = -m1 / k;
    to0 = (high - m0) / k, to1 = -m1 / k;
    if (k < 0.0) std::swap(from0, to0);
  }
  // Intersects [*from, *to] with the constraint's columns on row y.
  void clip(double y, double* from, double* to) const {
    if (!depends_on_x) {
      const double value = m0 + m1 * y;
      if (value < low || value > high) *from = 1.0, *to = 0.0;
      return;
    }
    *from = std::max(*from, from0 + from1 * y);
    *to = std::min(*to, to0 + to1 * y);
  }
};

// Grows [*from, *to] to take in the row's chord of the disc of squared radius r2 around c.
void add_disc_chord(const Point& c, double y, double r2, double* from, double* to) {
  const double dy = y - c.y;
  if (dy * dy > r2) return;
  const double half = std::sqrt(r2 - dy * dy);
  *from = std::min(*from, c.x - half);
  *to = std::max(*to, c.x + half);
}

// Adds the pixels within `radius` of segment pq to `band`.
void add_capsule(const Point& p, const Point& q, double radius, RowSpans* band) {
  const int width = band->size().width;
  const int top = static_cast<int>(std::max(0.0, std::ceil(std::min(p.y, q.y) - radius)));
  const int bottom = static_cast<int>(
      std::min(band->size().height - 1.0, std::floor(std::max(p.y, q.y) + radius)));
  const double r2 = radius * radius;
  const Point d = q - p;
  const double length = std::sqrt(d.x * d.x + d.y * d.y);
  // The rectangle between the discs: 0 <= (x - p).d <= |d|^2 and |(x - p) x d| <= r |d|, both
  // linear in the column x and the row y.
  const RowConstraint along(d.x, -p.x * d.x - p.y * d.y, d.y, 0.0, length * length);
  const RowConstraint across(d.y, -p.x * d.y + p.y * d.x, -d.x, -radius * length, radius * length);
  for (int y = top; y <= bottom; ++y) {
    double from = std::numeric_limits<double>::infinity();
    double to = -from;
    if (length > 0.0) {
      double low = -std::numeric_limits<double>::infinity(), high = -low;
      along.clip(y, &low, &high);
      across.clip(y, &low, &high);
      if (low <= high) from = low, to = high;
    }
    add_disc_chord(p, y, r2, &from, &to);
    add_disc_chord(q, y, r2, &from, &to);
    // Clamped first, so that the conversions below round as ceil and floor would (without
    // SSE4.1, std::ceil and std::floor are calls, most of this loop's time).
    from = std::max(from, -1.0);
    to = std::min(to, 1.0 * width);
    if (!(from <= to)) continue;
    int first = static_cast<int>(from), last = static_cast<int>(to);  // truncated towards 0
    first += first < from;
    last -= last > to;
    first = std::max(first, 0);
    last = std::min(last, width - 1);
    if (first <= last) band->add(y, first, last);
  }
}

}  // namespace

void band_spans(const Polygon& boundary, cv::Point offset, double radius, cv::Size size,
                RowSpans* band) {
  band->reset(size);
  if (boundary.empty() || size.empty() || !(radius >= 0.0)) return;
  // Far beyond any window, yet small enough that squares and products stay exact enough.
  constexpr double kLimit = 1e6;
  radius = std::min(radius, kLimit);
  auto local = [&](const Point& p) {
    const double x = p.x - offset.x, y = p.y - offset.y;
    return Point(std::isnan(x) ? kLimit : std::clamp(x, -kLimit, kLimit),
                 std::isnan(y) ? kLimit : std::clamp(y, -kLimit, kLimit));
  };
  const size_t n = boundary.size();
  for (size_t i = 0; i < n; ++i) {
    add_capsule(local(boundary[i]), local(boundary[(i + 1) % n]), radius, band);
  }
}

void draw_band_mask(const Polygon& boundary, cv::Point offset, double radius, cv::Size size,
                    cv::Mat* mask) {
  thread_local RowSpans band;
  band_spans(boundary, offset, radius, size, &band);
  band.draw(mask);
}

}  // namespace scbt
