// Points along a closed image boundary, each with the direction pointing into the object: where
// the boundary's depth is read (the object's side of an edge has the object's depth; the other
// side the background's, and the edge pixels a mix of both).
#pragma once

#include <cstddef>
#include <limits>
#include <vector>

#include "scbt/geometry/polygon.h"

namespace scbt {

// Where points along the edges are taken (pixel coordinates, bounds included): the depth image
// grown by the reach of a sample's depth window. Unbounded by default.
struct SampleRegion {
  double x_min = -std::numeric_limits<double>::infinity();
  double y_min = -std::numeric_limits<double>::infinity();
  double x_max = std::numeric_limits<double>::infinity();
  double y_max = std::numeric_limits<double>::infinity();
};

// Points along the edges are at most about this many (two more per edge at most): a boundary
// whose edges inside the region are longer than this many steps has them spaced more widely.
constexpr std::size_t kMaxEdgeSamples = std::size_t{1} << 16;

struct BoundarySample {
  Point pixel;
  Point inward;         // unit vector into the enclosed region
  bool vertex = false;  // a vertex of the polygon (not a point along an edge)
};

// Every vertex, and points along each edge at most `step` pixels apart, in boundary order --
// along the parts of the edges inside `region` only, where they are the same points as without
// it (an edge's points are spaced evenly from vertex to vertex). Beyond `max_edge_samples` points
// along the edges, the step grows to keep them to about that many. So the samples grow with the
// polygon's vertices, not with how far it reaches outside the region.
// At a vertex the inward direction bisects those of its two edges. Repeated consecutive vertices
// are skipped; a polygon with fewer than 3 distinct vertices or no area gives no samples.
std::vector<BoundarySample> sample_boundary_inward(const Polygon& polygon, double step,
                                                   const SampleRegion& region = {},
                                                   std::size_t max_edge_samples = kMaxEdgeSamples);

}  // namespace scbt
