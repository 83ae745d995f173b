#include "scbt/lines/band_mask.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "scbt/geometry/avx2_clones.h"

namespace scbt {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The columns x of row y where a linear constraint low <= k x + m0 + m1 y <= high holds, as
// x in [from0 + from1 y, to0 + to1 y] on the rows that pass holds_on_row (precomputed per edge so
// that a row costs no division and no branch). When k is 0 the bounds are infinite and the row
// test decides; otherwise the row test always passes.
struct RowConstraint {
  bool depends_on_x = false;
  double from0 = -kInfinity, from1 = 0.0, to0 = kInfinity, to1 = 0.0;
  double m0 = 0.0, m1 = 0.0, low = 0.0, high = 0.0;

  RowConstraint(double k, double m0_, double m1_, double low_, double high_) {
    if (std::abs(k) < 1e-12) {
      m0 = m0_, m1 = m1_, low = low_, high = high_;
      return;
    }
    depends_on_x = true;
    // (low - m0 - m1 y) / k and (high - m0 - m1 y) / k, in increasing order.
    from0 = (low_ - m0_) / k, from1 = -m1_ / k;
    to0 = (high_ - m0_) / k, to1 = -m1_ / k;
    if (k < 0.0) std::swap(from0, to0);
  }
  double from(double y) const { return from0 + from1 * y; }
  double to(double y) const { return to0 + to1 * y; }
  bool holds_on_row(double y) const {
    const double value = m0 + m1 * y;
    return !((value < low) | (value > high));  // both compared, so that it needs no branch
  }
};

// Square roots in place, two per instruction where SSE2 allows: std::sqrt in a loop does not
// vectorise, as it may set errno. Both round correctly, so the results are the same.
inline void sqrt_in_place(double* values, int count) {
  int i = 0;
#if defined(__SSE2__)
  for (; i + 2 <= count; i += 2) _mm_storeu_pd(values + i, _mm_sqrt_pd(_mm_loadu_pd(values + i)));
#endif
  for (; i < count; ++i) values[i] = std::sqrt(values[i]);
}

// The rows of the window that the half capsule of edge pq (below) can reach, a row more each way
// against rounding: q's disc, and the rectangle, whose corners lie r |d.x| / |d| above and below
// the segment's ends. Empty when *top > *bottom.
void half_capsule_rows(const Point& p, const Point& q, double radius, int height, int* top,
                       int* bottom) {
  const Point d = q - p;
  const double length = std::sqrt(d.x * d.x + d.y * d.y);
  double reach_top = q.y - radius, reach_bottom = q.y + radius;
  if (length > 0.0) {
    const double rise = radius * std::abs(d.x) / length;
    reach_top = std::min(reach_top, std::min(p.y, q.y) - rise);
    reach_bottom = std::max(reach_bottom, std::max(p.y, q.y) + rise);
  }
  *top = static_cast<int>(std::max(0.0, std::ceil(reach_top) - 1.0));
  *bottom = static_cast<int>(std::min(height - 1.0, std::floor(reach_bottom) + 1.0));
}

// The columns first[i] .. last[i] (empty when first[i] > last[i]) of row top + i, for i below
// `count`, within `radius` of segment pq or of the disc around q, but not those only the disc
// around p reaches: around a closed polyline every vertex is the end q of one edge, so each vertex
// disc is computed once, and the union is the same. The segment's rectangle and q's disc are a
// convex set (half a capsule), so each row holds one interval. `from` and `to` are scratch of
// `count` doubles. Whole passes over the rows, without branches, so that they vectorise.
SCBT_AVX2_CLONES void half_capsule_columns(const Point& p, const Point& q, double radius, int width,
                                           int top, int count, double* from, double* to, int* first,
                                           int* last) {
  const double r2 = radius * radius;
  const Point d = q - p;
  const double length = std::sqrt(d.x * d.x + d.y * d.y);
  // The rectangle between the discs: 0 <= (x - p).d <= |d|^2 and |(x - p) x d| <= r |d|, both
  // linear in the column x and the row y.
  const RowConstraint along(d.x, -p.x * d.x - p.y * d.y, d.y, 0.0, length * length);
  const RowConstraint across(d.y, -p.x * d.y + p.y * d.x, -d.x, -radius * length, radius * length);
  const bool has_rectangle = length > 0.0;
  const double qx = q.x, qy = q.y;  // not reloaded after each store (the arrays might alias q)
  // The half chord of q's disc on each row, in `from` (0 off the disc, where it is not used).
  double* half = from;
  for (int i = 0; i < count; ++i) {
    const double dy = (top + i) - qy;
    half[i] = std::max(r2 - dy * dy, 0.0);
  }
  sqrt_in_place(half, count);
  // Clamped to [-1, width], so that the conversions below round as ceil and floor would (and
  // stay in range even on empty rows). Comparisons all run on every row, results then picked: a
  // conditional one could trap, which keeps the compiler from vectorising.
  const double right = width;
  auto bound_row = [&](int i, bool row_tests) {
    const double y = top + i;
    const double low = std::max(along.from(y), across.from(y));
    const double high = std::min(along.to(y), across.to(y));
    const bool in_rectangle =
        row_tests ? has_rectangle & along.holds_on_row(y) & across.holds_on_row(y) & (low <= high)
                  : low <= high;
    double row_from = in_rectangle ? low : kInfinity;
    double row_to = in_rectangle ? high : -kInfinity;
    const double dy = y - qy;
    const bool in_disc = dy * dy <= r2;
    const double disc_from = std::min(row_from, qx - half[i]);
    const double disc_to = std::max(row_to, qx + half[i]);
    row_from = in_disc ? disc_from : row_from;
    row_to = in_disc ? disc_to : row_to;
    from[i] = std::min(std::max(row_from, -1.0), right);
    to[i] = std::max(std::min(row_to, right), -1.0);
  };
  // On slanted edges, most of them, the row tests always pass: a loop without them.
  if (has_rectangle && along.depends_on_x && across.depends_on_x) {
    for (int i = 0; i < count; ++i) bound_row(i, false);
  } else {
    for (int i = 0; i < count; ++i) bound_row(i, true);
  }
  for (int i = 0; i < count; ++i) {
    int column = static_cast<int>(from[i]);  // truncated towards 0
    first[i] = std::max(column + (column < from[i]), 0);
    column = static_cast<int>(to[i]);
    last[i] = std::min(column - (column > to[i]), width - 1);
  }
}

// Each row's union so far, as the spans the band already holds plus two open intervals: the one
// the latest edges grew and another (empty: first above last + 1, as kEmpty and -kEmpty are against
// any column). Neighbouring edges' intervals on a row mostly overlap or touch, and a band around a
// convex shape crosses a row twice, so the two open intervals take in most of them.
constexpr int kEmpty = std::numeric_limits<int>::max() / 2;
struct OpenIntervals {
  std::vector<int> first[2], last[2];  // [0]: the latest, [1]: the other
};

// Merges the columns first[k] .. last[k] of row top + k (empty when first[k] > last[k]), k below
// `count`, into the rows' open intervals (the arrays from row `top` on): into one it overlaps or
// touches, else it becomes the latest, the latest the other, and the other goes to the band (which
// merges spans), which is rare. Branchless passes that vectorise (the arrays are distinct, so
// marked restrict), but for the rare rows that give a span to the band.
SCBT_AVX2_CLONES void merge_rows(const int* __restrict first, const int* __restrict last, int top,
                                 int count, int* __restrict latest_first,
                                 int* __restrict latest_last, int* __restrict other_first,
                                 int* __restrict other_last, RowSpans* band) {
  auto touches = [](int f, int l, int open_first, int open_last) {
    return f <= open_last + 1 && open_first <= l + 1;
  };
  auto pushes_out = [&](int k) {  // the other interval, to the band
    // `&`, not `&&`: every load unconditional, so no branch.
    const int f = first[k], l = last[k], lf = latest_first[k], ll = latest_last[k];
    const int of = other_first[k], ol = other_last[k];
    return (f <= l) & (of <= ol) & ((f > ll + 1) | (lf > l + 1)) & ((f > ol + 1) | (of > l + 1));
  };
  int any_pushed_out = 0;  // usually none: a vectorised test spares the scalar pass
  for (int k = 0; k < count; ++k) any_pushed_out |= pushes_out(k);
  if (any_pushed_out) {
    for (int k = 0; k < count; ++k) {
      if (!pushes_out(k)) continue;
      band->add(top + k, other_first[k], other_last[k]);
      other_first[k] = kEmpty, other_last[k] = -kEmpty;
    }
  }
  for (int k = 0; k < count; ++k) {
    const int f = first[k], l = last[k];
    const int lf = latest_first[k], ll = latest_last[k], of = other_first[k], ol = other_last[k];
    const bool empty = f > l;
    const bool into_latest = !empty && touches(f, l, lf, ll);
    const bool into_other = !empty && !into_latest && touches(f, l, of, ol);
    const bool shifts = !empty && !into_latest && !into_other;
    latest_first[k] = into_latest ? std::min(lf, f) : shifts ? f : lf;
    latest_last[k] = into_latest ? std::max(ll, l) : shifts ? l : ll;
    other_first[k] = into_other ? std::min(of, f) : shifts ? lf : of;
    other_last[k] = into_other ? std::max(ol, l) : shifts ? ll : ol;
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
  const int width = size.width, height = size.height;
  thread_local std::vector<int> first, last;
  thread_local std::vector<double> from, to;
  thread_local OpenIntervals open;
  for (int slot = 0; slot < 2; ++slot) {
    open.first[slot].assign(height, kEmpty);
    open.last[slot].assign(height, -kEmpty);
  }
  first.resize(height);
  last.resize(height);
  from.resize(height);
  to.resize(height);
  const size_t n = boundary.size();
  for (size_t i = 0; i < n; ++i) {
    const Point p = local(boundary[i]), q = local(boundary[(i + 1) % n]);
    int top, bottom;
    half_capsule_rows(p, q, radius, height, &top, &bottom);
    if (top > bottom) continue;
    const int count = bottom - top + 1;
    half_capsule_columns(p, q, radius, width, top, count, from.data(), to.data(), first.data(),
                         last.data());
    merge_rows(first.data(), last.data(), top, count, open.first[0].data() + top,
               open.last[0].data() + top, open.first[1].data() + top, open.last[1].data() + top,
               band);
  }
  for (int y = 0; y < height; ++y) {
    for (int slot = 0; slot < 2; ++slot) {
      if (open.first[slot][y] <= open.last[slot][y]) {
        band->add(y, open.first[slot][y], open.last[slot][y]);
      }
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
