#include "scbt/geometry/boundary_query.h"

#include <algorithm>
#include <cmath>

#include "scbt/geometry/avx2_clones.h"

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
}

namespace {

// The box pass is most of a query; with AVX2 four boxes per instruction instead of two.
SCBT_AVX2_CLONES double nearest_edge_distance(const Polygon& boundary, const double* all_min_x,
                                              const double* all_max_x, const double* all_min_y,
                                              const double* all_max_y, const Point& p,
                                              size_t* hint) {
  const size_t n = boundary.size();
  auto edge_distance_sq = [&](size_t i) {
    return distance_sq_to_segment(p, boundary[i == 0 ? n - 1 : i - 1], boundary[i]);
  };
  size_t nearest = *hint < n ? *hint : 0;
  double best = edge_distance_sq(nearest);
  // The squared distances to the boxes are computed a block at a time in a branch-free loop the
  // compiler vectorises, then scanned in edge order as before (same values, same skips, so the
  // same answer to the last bit): the box test was most of a query's time.
  constexpr size_t kBlock = 64;
  double box_distance_sq[kBlock];
  for (size_t first = 0; first < n; first += kBlock) {
    const size_t count = std::min(kBlock, n - first);
    const double *min_x = all_min_x + first, *max_x = all_max_x + first;
    const double *min_y = all_min_y + first, *max_y = all_max_y + first;
    for (size_t k = 0; k < count; ++k) {
      const double dx = std::max(std::max(min_x[k] - p.x, 0.0), p.x - max_x[k]);
      const double dy = std::max(std::max(min_y[k] - p.y, 0.0), p.y - max_y[k]);
      box_distance_sq[k] = dx * dx + dy * dy;
    }
    for (size_t k = 0; k < count; ++k) {
      if (box_distance_sq[k] >= best) continue;  // the edge lies in its box
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

}  // namespace

double BoundaryQuery::distance(const Point& p, size_t* hint) const {
  const Polygon& boundary = *boundary_;
  if (boundary.size() < 2) return distance_to_boundary(p, boundary);
  return nearest_edge_distance(boundary, min_x_.data(), max_x_.data(), min_y_.data(), max_y_.data(),
                               p, hint);
}

}  // namespace scbt
