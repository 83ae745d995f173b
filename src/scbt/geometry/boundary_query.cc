#include "scbt/geometry/boundary_query.h"

#include <algorithm>
#include <cmath>

namespace scbt {

void BoundaryQuery::reset(const Polygon& boundary) {
  boundary_ = &boundary;
  const size_t n = boundary.size();
  min_x_.resize(n);
  max_x_.resize(n);
  min_y_.resize(n);
  max_y_.resize(n);
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point &a = boundary[j], &b = boundary[i];
    min_x_[i] = std::min(a.x, b.x);
    max_x_[i] = std::max(a.x, b.x);
    min_y_[i] = std::min(a.y, b.y);
    max_y_[i] = std::max(a.y, b.y);
  }
  const size_t runs = (n + kRun - 1) / kRun;
  run_min_x_.resize(runs);
  run_max_x_.resize(runs);
  run_min_y_.resize(runs);
  run_max_y_.resize(runs);
  for (size_t r = 0; r < runs; ++r) {
    const size_t first = r * kRun, end = std::min(n, first + kRun);
    run_min_x_[r] = *std::min_element(&min_x_[first], &min_x_[0] + end);
    run_max_x_[r] = *std::max_element(&max_x_[first], &max_x_[0] + end);
    run_min_y_[r] = *std::min_element(&min_y_[first], &min_y_[0] + end);
    run_max_y_[r] = *std::max_element(&max_y_[first], &max_y_[0] + end);
  }
}

double BoundaryQuery::distance(const Point& p, size_t* hint) const {
  const Polygon& boundary = *boundary_;
  const size_t n = boundary.size();
  if (n < 2) return distance_to_boundary(p, boundary);
  auto edge_distance_sq = [&](size_t i) {
    return distance_sq_to_segment(p, boundary[i == 0 ? n - 1 : i - 1], boundary[i]);
  };
  size_t nearest = *hint < n ? *hint : 0;
  double best = edge_distance_sq(nearest);
  // A run's box contains its edges' boxes, and the box distances are rounded monotonically, so
  // a run whose box is no nearer than the best so far holds no edge whose box is: skipping it
  // skips exactly the edges the scan in edge order would skip (same answer and nearest edge).
  // Within a run the edges' boxes are computed at once in a branch-free loop that vectorises,
  // then scanned in edge order.
  auto box_distance_sq = [&p](double min_x, double max_x, double min_y, double max_y) {
    const double dx = std::max(std::max(min_x - p.x, 0.0), p.x - max_x);
    const double dy = std::max(std::max(min_y - p.y, 0.0), p.y - max_y);
    return dx * dx + dy * dy;
  };
  double edge_box_sq[kRun];
  const size_t runs = run_min_x_.size();
  for (size_t r = 0; r < runs; ++r) {
    if (box_distance_sq(run_min_x_[r], run_max_x_[r], run_min_y_[r], run_max_y_[r]) >= best) {
      continue;
    }
    const size_t first = r * kRun;
    const size_t count = std::min(kRun, n - first);
    const double *min_x = &min_x_[first], *max_x = &max_x_[first];
    const double *min_y = &min_y_[first], *max_y = &max_y_[first];
    if (count == kRun) {
      for (size_t k = 0; k < kRun; ++k) {
        edge_box_sq[k] = box_distance_sq(min_x[k], max_x[k], min_y[k], max_y[k]);
      }
    } else {
      for (size_t k = 0; k < count; ++k) {
        edge_box_sq[k] = box_distance_sq(min_x[k], max_x[k], min_y[k], max_y[k]);
      }
    }
    for (size_t k = 0; k < count; ++k) {
      if (edge_box_sq[k] >= best) continue;  // the edge lies in its box
      const double d = edge_distance_sq(first + k);
      if (d < best) {
        best = d;
        nearest = first + k;
      }
    }
  }
  *hint = nearest;
  return std::sqrt(best);
}

}  // namespace scbt
