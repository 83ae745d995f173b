// Repeated point-to-boundary distance queries against one fixed closed polygon.
#pragma once

#include <cstddef>
#include <vector>

#include "scbt/geometry/polygon.h"

namespace scbt {

// Answers distance_to_boundary(p, boundary) (up to the last bit), faster when many points are asked
// in turn: every edge is visited, but the exact distance is computed only for edges whose bounding
// box is nearer than the best distance so far, starting from a hint (the nearest edge of a nearby
// point). Per frame, the tracker asks a few hundred points against a boundary of tens of edges, and
// most boxes are far from any one point. Keeps a reference to `boundary`; reusable across polygons.
class BoundaryQuery {
 public:
  BoundaryQuery() = default;
  explicit BoundaryQuery(const Polygon& boundary) { reset(boundary); }
  void reset(const Polygon& boundary);

  // distance_to_boundary(p, boundary); *hint (any value) is the edge to try first and becomes the
  // nearest edge (edge i joins vertex i - 1 to vertex i).
  double distance(const Point& p, size_t* hint) const;
  double distance(const Point& p) const {
    size_t hint = 0;
    return distance(p, &hint);
  }

 private:
  const Polygon* boundary_ = nullptr;
  // Bounding box of edge i, one array per side (so that the box test vectorises).
  std::vector<double> min_x_, max_x_, min_y_, max_y_;
};

}  // namespace scbt
