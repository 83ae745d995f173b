// Stage 5: Bidirectional Shortest Path cycle candidates (paper §III-D, Fig. 4e, Algorithm 1).
#pragma once

#include <vector>

#include "scbt/geometry/polygon.h"
#include "scbt/grouping/segment_graph.h"

namespace scbt {

struct CycleCandidate {
  std::vector<int> vertices;  // graph vertex ids in cycle order; the cycle closes back to front
  double gap_length = 0.0;    // |B_G|: total length of generated edges on the cycle
  double area = 0.0;          // enclosed area (shoelace)
  int seed_edge = -1;         // the detected edge e_i the cycle was grown from
};

struct BdspOptions {
  // Seeds are every `seed_stride`-th detected segment (the paper samples every other one: 2).
  int seed_stride = 2;
};

// For every sampled detected edge e_i = (s1, s2): block e_i, find shortest paths from s1 and s2,
// and for every other detected edge e_j close the cycle e_i + path(s1 -> v_j) + path(v_j -> s2)
// through its first endpoint v_j. Where the two paths merge before v_j, the shared tail is cut
// off so that every candidate is a cycle that visits each vertex once. A third vertex whose paths
// meet where an earlier one's did (same cycle) is skipped, as are cycles of fewer than three
// vertices; other repeats of a cycle can remain (they carry identical gap and area, so they never
// change the choice).
std::vector<CycleCandidate> search_cycle_candidates(const SegmentGraph& graph,
                                                    const BdspOptions& options = {});

// The polygon of a candidate's vertices.
Polygon candidate_polygon(const SegmentGraph& graph, const CycleCandidate& candidate);

}  // namespace scbt
