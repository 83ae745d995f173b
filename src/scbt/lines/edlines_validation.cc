#include <algorithm>
#include <cmath>

#include "scbt/lines/edlines.h"

namespace scbt {
namespace {

constexpr int kAcceptWithoutTest = 80;  // lines of this many pixels are valid as they are
constexpr int kRectTestUpTo = 25;       // lines up to this many pixels: rectangle test only
// cos(22.5 deg): a pixel is aligned when its level line is within 22.5 degrees of the line.
const double kAlignedCos = std::cos(22.5 * M_PI / 180.0);
const double kAlignedCos2 = kAlignedCos * kAlignedCos;
constexpr double kAlignedProbability = 0.125;

}  // namespace

int EdLines::min_aligned(int n) {
  // Row n of the table: log10 of the binomial tail P[at least k of n aligned], k = 0..n, computed
  // once (from k = n down, adding terms in log space) and kept for every later call.
  while (static_cast<int>(tail_start_.size()) <= n) {
    const int m = static_cast<int>(tail_start_.size());
    tail_start_.push_back(static_cast<int>(log10_tail_.size()));
    log10_tail_.resize(log10_tail_.size() + m + 1);
    double* row = log10_tail_.data() + tail_start_.back();
    const double p = kAlignedProbability;
    double term = m * std::log(p);  // ln P[exactly m aligned]
    double tail = term;
    row[m] = tail / std::log(10.0);
    for (int k = m; k >= 1; --k) {
      term += std::log(static_cast<double>(k) / (m - k + 1)) + std::log((1.0 - p) / p);
      tail = std::max(tail, term) + std::log1p(std::exp(-std::abs(tail - term)));
      row[k - 1] = std::min(tail / std::log(10.0), 0.0);
    }
  }
  // The fewest aligned pixels with NFA = NT * tail <= 1 (n + 1: none).
  const double* row = log10_tail_.data() + tail_start_[n];
  int lo = 0, hi = n + 1;
  while (lo < hi) {
    const int mid = (lo + hi) / 2;
    if (log_nt_ + row[mid] <= 0.0) {
      hi = mid;
    } else {
      lo = mid + 1;
    }
  }
  return lo;
}

// A-contrario test of a line: count the pixels whose level line (on the unsmoothed image) is
// aligned with it, first along the line's own edge pixels (longer lines), then in the width-2
// rectangle around the line.
bool EdLines::validate(const Line& line, const cv::Mat& gray) {
  if (line.len >= kAcceptWithoutTest) return true;
  const double dx = line.ex - line.sx, dy = line.ey - line.sy;
  const double length = std::sqrt(dx * dx + dy * dy);
  if (length <= 0.0) return false;
  const double ux = dx / length, uy = dy / length;
  auto aligned_at = [&](int r, int c) {
    const std::uint8_t* above = gray.ptr<std::uint8_t>(r - 1);
    const std::uint8_t* row = gray.ptr<std::uint8_t>(r);
    const std::uint8_t* below = gray.ptr<std::uint8_t>(r + 1);
    // Prewitt-like 3x3 differences.
    const int gx =
        (above[c + 1] - above[c - 1]) + (row[c + 1] - row[c - 1]) + (below[c + 1] - below[c - 1]);
    const int gy =
        (below[c - 1] - above[c - 1]) + (below[c] - above[c]) + (below[c + 1] - above[c + 1]);
    // A pixel without gradient has level-line angle 0 in the reference implementation (its
    // atan2(0, 0) = 0), so it counts as aligned with lines within 22.5 degrees of horizontal.
    if (gx == 0 && gy == 0) return std::abs(ux) >= kAlignedCos;
    // The level line runs along (-gy, gx); aligned when within 22.5 degrees of the line (mod pi).
    const double along = -gy * ux + gx * uy;
    return along * along >= kAlignedCos2 * (static_cast<double>(gx) * gx + gy * gy);
  };
  auto inside = [&](int r, int c) { return r > 0 && r < height_ - 1 && c > 0 && c < width_ - 1; };

  // Both tests know how many pixels they look at before looking, so each stops as soon as the
  // aligned ones reach the number needed, or can no longer reach it (same answer, fewer pixels).
  if (line.len > kRectTestUpTo) {
    const int begin = seg_start_[line.segment] + line.first;
    const int end = std::min(begin + line.len, seg_end_[line.segment]);
    int count = 0;
    for (int i = begin; i < end; ++i) {
      count += inside(seg_pixels_[i] / width_, seg_pixels_[i] % width_) ? 1 : 0;
    }
    if (count > 0) {
      const int needed = min_aligned(count);
      int aligned = 0, left = count;
      for (int i = begin; i < end && aligned < needed && aligned + left >= needed; ++i) {
        const int r = seg_pixels_[i] / width_, c = seg_pixels_[i] % width_;
        if (!inside(r, c)) continue;
        --left;
        aligned += aligned_at(r, c) ? 1 : 0;
      }
      if (aligned >= needed) return true;
    }
  }
  // Rectangle of width 2 centred on the line: pixel centres p with 0 <= (p - s).u <= length and
  // |(p - s) x u| <= 1.
  int count = 0;
  row_ranges_.clear();
  const int r0 = std::max(1, static_cast<int>(std::floor(std::min(line.sy, line.ey) - 1.0)));
  const int r1 =
      std::min(height_ - 2, static_cast<int>(std::ceil(std::max(line.sy, line.ey) + 1.0)));
  for (int r = r0; r <= r1; ++r) {
    // x range where both constraints hold on this row: each is linear in x.
    double lo = -1e18, hi = 1e18;
    auto clip = [&](double coef, double constant, double min_value, double max_value) {
      // min_value <= coef * x + constant <= max_value
      if (std::abs(coef) < 1e-12) {
        if (constant < min_value || constant > max_value) lo = 1.0, hi = 0.0;
        return;
      }
      double a = (min_value - constant) / coef, b = (max_value - constant) / coef;
      if (a > b) std::swap(a, b);
      lo = std::max(lo, a);
      hi = std::min(hi, b);
    };
    const double ry = r - line.sy;
    clip(ux, -line.sx * ux + ry * uy, 0.0, length);  // along
    clip(-uy, line.sx * uy + ry * ux, -1.0, 1.0);    // across: (p - s) x u = px*uy - py*ux
    // Rows and columns are clipped to the interior, where every pixel has its 3x3 neighbours.
    const int c0 = std::max(1, static_cast<int>(std::ceil(lo - 1e-9)));
    const int c1 = std::min(width_ - 2, static_cast<int>(std::floor(hi + 1e-9)));
    if (c0 > c1) continue;
    row_ranges_.push_back({r, c0, c1});
    count += c1 - c0 + 1;
  }
  if (count == 0) return false;
  const int needed = min_aligned(count);
  int aligned = 0, left = count;
  for (const RowRange& range : row_ranges_) {
    for (int c = range.first; c <= range.last; ++c) {
      if (aligned >= needed || aligned + left < needed) return aligned >= needed;
      --left;
      aligned += aligned_at(range.row, c) ? 1 : 0;
    }
  }
  return aligned >= needed;
}

}  // namespace scbt
