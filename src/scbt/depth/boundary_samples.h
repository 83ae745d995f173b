// Points along a closed image boundary, each with the direction pointing into the object: where
// the boundary's depth is read (the object's side of an edge has the object's depth; the other
// side the background's, and the edge pixels a mix of both).
#pragma once

#include <vector>

#include "scbt/geometry/polygon.h"

namespace scbt {

struct BoundarySample {
  Point pixel;
  Point inward;         // unit vector into the enclosed region
  bool vertex = false;  // a vertex of the polygon (not a point along an edge)
};

// Every vertex, and points along each edge at most `step` pixels apart, in boundary order.
// At a vertex the inward direction bisects those of its two edges. Repeated consecutive vertices
// are skipped; a polygon with fewer than 3 distinct vertices or no area gives no samples.
std::vector<BoundarySample> sample_boundary_inward(const Polygon& polygon, double step);

}  // namespace scbt
