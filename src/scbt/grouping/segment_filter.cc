#include "scbt/grouping/segment_filter.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace scbt {
namespace {

// The boundary's edges with their bounding boxes. A point's least distance visits every edge,
// but computes the exact distance only to edges whose box is nearer than the best so far, and
// starts from a hint (the nearest edge of a nearby point): detected segments come in batches of
// a few hundred against a boundary of tens of edges, and most boxes are far from any one point.
class BoundaryEdges {
 public:
  explicit BoundaryEdges(const Polygon& boundary) : boundary_(boundary) {
    const size_t n = boundary.size();
    boxes_.resize(n);
    for (size_t i = 0, j = n - 1; i < n; j = i++) {
      const Point &a = boundary[j], &b = boundary[i];
      boxes_[i] = {std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y), std::max(a.y, b.y)};
    }
  }

  // distance_to_boundary(p, boundary), exactly; *hint is the edge to try first and becomes
  // the nearest edge.
  double distance(const Point& p, size_t* hint) const {
    const size_t n = boundary_.size();
    if (n < 2) return distance_to_boundary(p, boundary_);
    size_t nearest = *hint < n ? *hint : 0;
    double best = edge_distance_sq(p, nearest);
    for (size_t i = 0; i < n; ++i) {
      const Box& box = boxes_[i];
      const double dx = std::max({box.min_x - p.x, 0.0, p.x - box.max_x});
      const double dy = std::max({box.min_y - p.y, 0.0, p.y - box.max_y});
      if (dx * dx + dy * dy >= best) continue;  // the edge lies in its box
      const double d = edge_distance_sq(p, i);
      if (d < best) {
        best = d;
        nearest = i;
      }
    }
    *hint = nearest;
    return std::sqrt(best);
  }

 private:
  struct Box {
    double min_x, max_x, min_y, max_y;
  };
  // Edge i runs from vertex i - 1 to vertex i, as distance_to_boundary walks them.
  double edge_distance_sq(const Point& p, size_t i) const {
    const size_t j = i == 0 ? boundary_.size() - 1 : i - 1;
    return distance_sq_to_segment(p, boundary_[j], boundary_[i]);
  }

  const Polygon& boundary_;
  std::vector<Box> boxes_;
};

}  // namespace

double mean_distance_to_boundary(const Segment& segment, const Polygon& boundary) {
  return (distance_to_boundary(segment.a, boundary) + distance_to_boundary(segment.b, boundary) +
          distance_to_boundary(segment.midpoint(), boundary)) /
         3.0;
}

std::vector<Segment> filter_segments_near_boundary(const std::vector<Segment>& segments,
                                                   const Polygon& boundary,
                                                   double max_mean_distance) {
  std::vector<Segment> kept;
  filter_segments_near_boundary(segments, boundary, max_mean_distance, &kept);
  return kept;
}

void filter_segments_near_boundary(const std::vector<Segment>& segments, const Polygon& boundary,
                                   double max_mean_distance, std::vector<Segment>* kept) {
  kept->clear();
  if (boundary.empty()) return;
  const BoundaryEdges edges(boundary);
  // Distances are non-negative, so a sum that already reaches 3x the bound cannot get below it.
  const double sum_bound = 3.0 * max_mean_distance;
  size_t hint = 0;
  for (const Segment& segment : segments) {
    const double da = edges.distance(segment.a, &hint);
    if (!(da < sum_bound)) continue;
    const double db = edges.distance(segment.b, &hint);
    if (!(da + db < sum_bound)) continue;
    const double dm = edges.distance(segment.midpoint(), &hint);
    if ((da + db + dm) / 3.0 < max_mean_distance) kept->push_back(segment);
  }
}

}  // namespace scbt
