// Repeated point-to-boundary distance queries against one fixed closed polygon.
#pragma once

#include <cstddef>
#include <vector>

#include "scbt/geometry/polygon.h"

namespace scbt {

// Answers distance_to_boundary(p, boundary) (up to the last bit), faster when many points are asked
// in turn: the exact distance is computed only for edges whose bounding box is nearer than the
// best distance so far, starting from a hint (the nearest edge of a nearby point), and the edges
// are boxed in runs of consecutive ones too, so that a run whose box is farther is skipped whole.
// Per frame, the tracker asks a few hundred points against a boundary of tens of edges, and most
// boxes are far from any one point. Keeps a reference to `boundary`; reusable across polygons.
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
  // Edges per run: a boundary of tens of edges has a handful of runs, and a point near it is
  // near one or two of them.
  static constexpr size_t kRun = 8;
  // Bounding box of edge i, one array per side (so that the box test vectorises).
  std::vector<double> min_x_, max_x_, min_y_, max_y_;
  // Bounding box of run r (edges r * kRun ..), the union of its edges' boxes.
  std::vector<double> run_min_x_, run_max_x_, run_min_y_, run_max_y_;
};

}  // namespace scbt
