#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>

#include "scbt/lines/edlines.h"

namespace scbt {
namespace {

constexpr double kInitialFitError = 0.5;  // RMS error of a line's first min_length pixels
constexpr int kMaxOutliers = 5;           // consecutive far pixels that end a line

// The means of n points (u_i, v_i) and their centred sums of squares and products.
struct CentredSums {
  double mu = 0.0, mv = 0.0;
  double suu = 0.0, suv = 0.0, svv = 0.0;  // svv only when asked for
};

CentredSums centred_sums(const double* u, const double* v, int n, bool with_svv) {
  CentredSums s;
  for (int i = 0; i < n; ++i) s.mu += u[i], s.mv += v[i];
  s.mu /= n;
  s.mv /= n;
  for (int i = 0; i < n; ++i) {
    s.suu += (u[i] - s.mu) * (u[i] - s.mu);
    s.suv += (u[i] - s.mu) * (v[i] - s.mv);
    if (with_svv) s.svv += (v[i] - s.mv) * (v[i] - s.mv);
  }
  return s;
}

// Least-squares line v = a + b u through (u_i, v_i); RMS orthogonal distance in `error`.
void fit_uv(const double* u, const double* v, int n, double* a, double* b, double* error) {
  const CentredSums s = centred_sums(u, v, n, false);
  *b = s.suu > 0.0 ? s.suv / s.suu : 0.0;
  *a = s.mv - *b * s.mu;
  if (error != nullptr) {
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
      const double r = v[i] - *a - *b * u[i];
      sum += r * r;
    }
    *error = std::sqrt(sum / (n * (1.0 + *b * *b)));
  }
}

double line_distance(double x, double y, double a, double b, bool invert) {
  const double u = invert ? y : x, v = invert ? x : y;
  return std::abs(v - a - b * u) / std::sqrt(1.0 + b * b);
}

void closest_point(double x, double y, double a, double b, bool invert, double* px, double* py) {
  const double u = invert ? y : x, v = invert ? x : y;
  const double t = (u + (v - a) * b) / (1.0 + b * b);
  const double pu = t, pv = a + b * t;
  *px = invert ? pv : pu;
  *py = invert ? pu : pv;
}

}  // namespace

void EdLines::fit_lines(int min_length) {
  for (size_t s = 0; s < seg_start_.size(); ++s) split_segment(static_cast<int>(s), min_length);
}

// Splits one edge segment into lines: fit min_length pixels (sliding on by one pixel while the
// fit is poor), then extend while pixels stay near the line, refitting on every extension.
void EdLines::split_segment(int segment, int min_length) {
  const int begin = seg_start_[segment];
  const int total = seg_end_[segment] - begin;
  if (total < min_length) return;
  xs_.resize(total);
  ys_.resize(total);
  for (int i = 0; i < total; ++i) {
    xs_[i] = seg_pixels_[begin + i] % width_;
    ys_[i] = seg_pixels_[begin + i] / width_;
  }
  int first = 0;  // first pixel not yet in a line
  while (total - first >= min_length) {
    // A good initial fit.
    double a = 0.0, b = 0.0, error = 0.0;
    bool invert = false, found = false;
    for (; total - first >= min_length; ++first) {
      const double* x = xs_.data() + first;
      const double* y = ys_.data() + first;
      const CentredSums spread = centred_sums(x, y, min_length, true);
      invert = spread.suu < spread.svv;  // steep: x = a + b y
      fit_uv(invert ? y : x, invert ? x : y, min_length, &a, &b, &error);
      if (error <= kInitialFitError) {
        found = true;
        break;
      }
    }
    if (!found) return;
    const double* x = xs_.data() + first;
    const double* y = ys_.data() + first;
    const int n = total - first;
    int len = min_length;  // pixels fitted so far (from x[0])
    int last_good = min_length - 1;
    int index = min_length;
    // As in the reference implementation, a fit that reaches the end of the segment without a
    // pixel left to extend it to makes no line.
    if (index >= n) return;
    while (index < n) {
      const int start = index;
      int good = 0, bad = 0;
      for (; index < n; ++index) {
        if (line_distance(x[index], y[index], a, b, invert) <= params_.line_fit_error) {
          last_good = index;
          ++good;
          bad = 0;
        } else if (++bad >= kMaxOutliers) {
          break;
        }
      }
      if (good < 2) break;
      len += last_good - start + 1;
      fit_uv(invert ? y : x, invert ? x : y, len, &a, &b, nullptr);
      index = last_good + 1;
    }
    // Ends: the first and last pixels near the line, projected on it.
    int s = 0;
    while (s < last_good && line_distance(x[s], y[s], a, b, invert) > params_.line_fit_error) ++s;
    int e = last_good;
    while (e > s && line_distance(x[e], y[e], a, b, invert) > params_.line_fit_error) --e;
    Line line{a, b, invert, 0, 0, 0, 0, segment, first + s, e - s + 1};
    closest_point(x[s], y[s], a, b, invert, &line.sx, &line.sy);
    closest_point(x[e], y[e], a, b, invert, &line.ex, &line.ey);
    if (line.sx != line.ex || line.sy != line.ey) lines_.push_back(line);
    first += e + 1;
  }
}

// Joins consecutive collinear lines of each edge segment, and its last line with its first.
void EdLines::join_collinear_lines() {
  size_t kept = 0;
  for (size_t i = 0; i < lines_.size();) {
    const int segment = lines_[i].segment;
    const size_t first = kept;
    lines_[kept++] = lines_[i++];
    for (; i < lines_.size() && lines_[i].segment == segment; ++i) {
      if (!try_join(&lines_[kept - 1], lines_[i])) lines_[kept++] = lines_[i];
    }
    if (kept - 1 > first && try_join(&lines_[first], lines_[kept - 1])) --kept;
  }
  lines_.resize(kept);
}

bool EdLines::try_join(Line* l1, const Line& l2) const {
  const Point s1(l1->sx, l1->sy), e1(l1->ex, l1->ey), s2(l2.sx, l2.sy), e2(l2.ex, l2.ey);
  const double gap =
      std::min({cv::norm(s1 - s2), cv::norm(s1 - e2), cv::norm(e1 - s2), cv::norm(e1 - e2)});
  if (gap > params_.max_line_gap) return false;
  const bool first_longer = cv::norm(s1 - e1) > cv::norm(s2 - e2);
  const Line& longer = first_longer ? *l1 : l2;
  const Line& shorter = first_longer ? l2 : *l1;
  const double error = (line_distance(shorter.sx, shorter.sy, longer.a, longer.b, longer.invert) +
                        line_distance((shorter.sx + shorter.ex) / 2, (shorter.sy + shorter.ey) / 2,
                                      longer.a, longer.b, longer.invert) +
                        line_distance(shorter.ex, shorter.ey, longer.a, longer.b, longer.invert)) /
                       3.0;
  if (error > params_.max_join_error) return false;
  // The joined line spans the two ends farthest apart (in L1 distance).
  const Point candidates[4][2] = {{s1, s2}, {s1, e2}, {e1, s2}, {e1, e2}};
  int pick = 0;
  double widest = -1.0;
  for (int k = 0; k < 4; ++k) {
    const Point d = candidates[k][0] - candidates[k][1];
    const double l1_distance = std::abs(d.x) + std::abs(d.y);
    if (l1_distance > widest) widest = l1_distance, pick = k;
  }
  // Oriented as the reference implementation does: s1 -> s2, s1 -> e2, s2 -> e1, e1 -> e2.
  const Point from = pick == 2 ? s2 : candidates[pick][0];
  const Point to = pick == 2 ? e1 : candidates[pick][1];
  l1->sx = from.x, l1->sy = from.y, l1->ex = to.x, l1->ey = to.y;
  if (l1->first + l1->len + 5 >= l2.first) {
    l1->len += l2.len;
  } else if (l2.len > l1->len) {
    l1->first = l2.first;
    l1->len = l2.len;
  }
  // The line through the new ends.
  const double dx = to.x - from.x, dy = to.y - from.y;
  l1->invert = std::abs(dx) < std::abs(dy);
  const double du = l1->invert ? dy : dx, dv = l1->invert ? dx : dy;
  const double u0 = l1->invert ? from.y : from.x, v0 = l1->invert ? from.x : from.y;
  l1->b = du != 0.0 ? dv / du : 0.0;
  l1->a = v0 - l1->b * u0;
  return true;
}

}  // namespace scbt
