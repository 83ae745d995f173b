// Boundary distances between one fixed previous boundary and many cycles of one SegmentGraph,
// the inner loop of the stabilised choice (boundary_choice.h).
#pragma once

#include <vector>

#include "scbt/geometry/boundary_query.h"
#include "scbt/geometry/polygon.h"
#include "scbt/graph/segment_graph.h"

namespace scbt {

// Distances to the previous boundary already computed for some segments (the distance filter's,
// segment_filter.h): distances[3i], [3i + 1] and [3i + 2] are those of segments[i].a, .b and
// .midpoint(). A distance depends on the point alone, so the cache takes them for the graph's
// vertices and detected edges at those very points instead of asking again.
struct KnownSegmentDistances {
  const std::vector<Segment>* segments = nullptr;
  const std::vector<double>* distances = nullptr;
};

// Near-tied candidates of one frame share most of their vertices and edges, so the distances
// that make up boundary_distance(cycle, previous) are cached per graph vertex and edge and
// computed at most once per frame:
//  - cycle -> previous: per vertex and per edge midpoint, its distance to the previous boundary;
//  - previous -> cycle: per edge, the squared distances from the previous boundary's sample
//    points (vertices and edge midpoints) to it; a cycle's distance from a sample is the least
//    over its edges.
// Buffers are reused across frames. Values equal boundary_distance on the cycle's polygon up to
// rounding (an edge's distances are computed in the graph's orientation of the edge).
class BoundaryDistanceCache {
 public:
  // Starts a frame: forgets everything cached for the previous graph or boundary, then takes
  // what `known` (optional, distances to this `previous`) gives.
  void reset(const SegmentGraph& graph, const Polygon& previous,
             const KnownSegmentDistances* known = nullptr);

  // Length-weighted mean distance from the cycle (graph vertex ids, closing back to front) to
  // the previous boundary: the cheap direction, O(cycle length) once cached. When `edges` is
  // given, the graph edge (or -1) joining each vertex's predecessor to it is appended to it.
  double mean_distance_from_cycle(const std::vector<int>& cycle, std::vector<int>* edges = nullptr);
  // Length-weighted mean distance from the previous boundary to the cycle. `edges` (optional):
  // what mean_distance_from_cycle appended for this cycle, one per vertex.
  double mean_distance_to_cycle(const std::vector<int>& cycle, const int* edges = nullptr);
  // boundary_distance(candidate polygon, previous): the larger of the two.
  double boundary_distance(const std::vector<int>& cycle) {
    const double from = mean_distance_from_cycle(cycle);
    const double to = mean_distance_to_cycle(cycle);
    return from > to ? from : to;
  }

 private:
  // The edge joining u and v, or -1 (cycles handed in need not use graph edges).
  int edge_between(int u, int v) const;
  void take_known(const KnownSegmentDistances& known);
  double vertex_distance(int v);
  double midpoint_distance(int edge, const Point& a, const Point& b);
  // One edge's share of mean_distance_from_cycle, walked from a to b: its length and its
  // length-weighted Simpson sum.
  struct EdgeTerm {
    double length;
    double weighted;
  };
  EdgeTerm edge_term(int edge, int from, int to);
  // Squared distances from every sample of the previous boundary to segment [a, b], cached
  // under `edge` when it is >= 0.
  const double* sample_distances_sq(int edge, const Point& a, const Point& b);

  const SegmentGraph* graph_ = nullptr;
  const Polygon* previous_ = nullptr;
  BoundaryQuery query_;  // distances to the previous boundary
  size_t hint_ = 0;      // its nearest edge for the last point asked
  // NaN: not computed yet.
  std::vector<double> vertex_distance_;
  std::vector<double> midpoint_distance_;
  // Per edge and direction (2 * edge, + 1 when walked from v to u), its EdgeTerm: a cycle's
  // mean distance is then a sum of cached terms, added in the same order as before. The sum
  // inside a term is not symmetric in rounding, hence one per direction.
  std::vector<EdgeTerm> edge_term_;
  // Samples of the previous boundary: its vertex i is sample 2i, the midpoint of its edge
  // (i, i+1) is sample 2i+1. Coordinates in two arrays, so that a row's loop vectorises.
  std::vector<double> sample_x_, sample_y_;
  std::vector<double> previous_edge_length_;
  double previous_length_ = 0.0;
  // Per edge, the offset of its row of sample_x_.size() squared distances in `rows_`; -1 if none.
  std::vector<int> row_offset_;
  std::vector<double> rows_;
  std::vector<double> scratch_row_;
  std::vector<double> nearest_sq_;
};

}  // namespace scbt
