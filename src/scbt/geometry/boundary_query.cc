#include "scbt/geometry/boundary_query.h"

#include <algorithm>
#include <cmath>

namespace scbt {

void BoundaryQuery::reset(const Polygon& boundary) {
  boundary_ = &boundary;
  const size_t n = boundary.size();
  boxes_.resize(n);
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point &a = boundary[j], &b = boundary[i];
    boxes_[i] = {std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y), std::max(a.y, b.y)};
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
  for (size_t i = 0; i < n; ++i) {
    const Box& box = boxes_[i];
    const double dx = std::max({box.min_x - p.x, 0.0, p.x - box.max_x});
    const double dy = std::max({box.min_y - p.y, 0.0, p.y - box.max_y});
    if (dx * dx + dy * dy >= best) continue;  // the edge lies in its box
    const double d = edge_distance_sq(i);
    if (d < best) {
      best = d;
      nearest = i;
    }
  }
  *hint = nearest;
  return std::sqrt(best);
}

}  // namespace scbt
