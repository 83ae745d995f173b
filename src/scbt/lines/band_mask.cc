#include "scbt/lines/band_mask.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

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

struct RowInterval {
  int row, first, last;  // columns first .. last of `row`
};

// Appends, row by row, the pixels within `radius` of segment pq or of the disc around q, but
// not those only the disc around p reaches: around a closed polyline every vertex is the end q
// of one edge, so each vertex disc is computed once, and the union is the same. The segment's
// rectangle and q's disc are a convex set (half a capsule), so each row holds one interval.
void append_half_capsule(const Point& p, const Point& q, double radius, cv::Size size,
                         std::vector<RowInterval>* out, std::vector<int>* last_of_row) {
  const int width = size.width;
  const double r2 = radius * radius;
  const Point d = q - p;
  const double length = std::sqrt(d.x * d.x + d.y * d.y);
  // Rows it can reach (a row more each way against rounding): q's disc, and the rectangle,
  // whose corners lie r |d.x| / |d| above and below the segment's ends.
  double reach_top = q.y - radius, reach_bottom = q.y + radius;
  if (length > 0.0) {
    const double rise = radius * std::abs(d.x) / length;
    reach_top = std::min(reach_top, std::min(p.y, q.y) - rise);
    reach_bottom = std::max(reach_bottom, std::max(p.y, q.y) + rise);
  }
  const int top = static_cast<int>(std::max(0.0, std::ceil(reach_top) - 1.0));
  const int bottom = static_cast<int>(std::min(size.height - 1.0, std::floor(reach_bottom) + 1.0));
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
    if (first > last) continue;
    // Neighbouring edges' intervals on a row mostly overlap: the previous one of this row
    // takes in this one when they overlap or touch, which leaves few for band_spans to sort.
    int& previous = (*last_of_row)[y];
    RowInterval* merged = previous >= 0 ? &(*out)[previous] : nullptr;
    if (merged != nullptr && first <= merged->last + 1 && merged->first <= last + 1) {
      merged->first = std::min(merged->first, first);
      merged->last = std::max(merged->last, last);
    } else {
      previous = static_cast<int>(out->size());
      out->push_back({y, first, last});
    }
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
  thread_local std::vector<RowInterval> intervals, by_row;
  thread_local std::vector<int> row_start, last_of_row;
  intervals.clear();
  last_of_row.assign(size.height, -1);
  const size_t n = boundary.size();
  for (size_t i = 0; i < n; ++i) {
    append_half_capsule(local(boundary[i]), local(boundary[(i + 1) % n]), radius, size, &intervals,
                        &last_of_row);
  }
  // Grouped by row (counting sort), then each row's handful sorted by column and merged: cheaper
  // than merging each interval into the row's spans as it comes.
  row_start.assign(static_cast<size_t>(size.height) + 1, 0);
  for (const RowInterval& i : intervals) ++row_start[i.row + 1];
  for (int r = 0; r < size.height; ++r) row_start[r + 1] += row_start[r];
  by_row.resize(intervals.size());
  for (const RowInterval& i : intervals) by_row[row_start[i.row]++] = i;
  for (int r = size.height; r > 0; --r) row_start[r] = row_start[r - 1];
  row_start[0] = 0;
  for (int r = 0; r < size.height; ++r) {
    RowInterval* begin = by_row.data() + row_start[r];
    RowInterval* end = by_row.data() + row_start[r + 1];
    for (RowInterval* i = begin + 1; i < end; ++i) {  // insertion sort by first column
      const RowInterval moving = *i;
      RowInterval* at = i;
      for (; at > begin && (at - 1)->first > moving.first; --at) *at = *(at - 1);
      *at = moving;
    }
    for (const RowInterval* i = begin; i < end;) {
      const int first = i->first;
      int last = i->last;
      for (++i; i < end && i->first <= last + 1; ++i) last = std::max(last, i->last);
      band->add(r, first, last);
    }
  }
}

void draw_band_mask(const Polygon& boundary, cv::Point offset, double radius, cv::Size size,
                    cv::Mat* mask) {
  thread_local RowSpans band;
  band_spans(boundary, offset, radius, size, &band);
  band.draw(mask);
}

}  // namespace scbt
