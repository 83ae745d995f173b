// The segment graph with its detected segments contracted, for BDSP's shortest paths (bdsp.h).
#pragma once

#include <vector>

#include "scbt/graph/segment_graph.h"

namespace scbt {

// A detected edge weighs 0, so both endpoints of a detected segment are at the same distance
// from any root that is neither of them. A search over "units" instead of vertices settles
// about half as many nodes and relaxes fewer arcs: one unit per detected segment whose two
// endpoints have no other detected edge, one unit per remaining vertex (those where detected
// segments meet keep their zero-weight edges as arcs). Between two units only the lightest
// edge is kept, as one arc each way.
struct SegmentUnits {
  struct Arc {
    int unit;  // the unit it leads to
    int from;  // the graph vertex it leaves (in its own unit)
    int to;    // the graph vertex it reaches (in `unit`)
    double weight;
  };

  int num_units = 0;
  std::vector<int> unit_of;  // per graph vertex
  // Per graph vertex: the other endpoint of its unit's segment, -1 in a one-vertex unit.
  std::vector<int> partner;
  // Arcs of unit u: arcs[arc_begin[u] .. arc_begin[u + 1]), sorted by weight.
  std::vector<int> arc_begin;
  std::vector<Arc> arcs;
  std::vector<int> reverse;  // per arc: the index of the same edge's arc the other way

  // Buffers reused by the next build (nothing is allocated once they have grown).
  std::vector<int> scratch_count, scratch_stamp, scratch_slot;
  std::vector<double> scratch_weight;
};

// Contracts `graph` into `units` (its buffers reused).
void build_segment_units(const SegmentGraph& graph, SegmentUnits* units);

// Leaves out the arcs X - Y that no search needs: those with a detour X - Z - Y shorter by more
// than `margin` (far above rounding) that every search can take. A search may "open" units
// (BDSP splits its seed's unit and rebuilds its arcs): opened_by[Z] is -1 for a unit no search
// opens, the one search that opens it, or -2 for several. A detour whose two arcs touch the same
// vertex of Z stays whole in an opened Z (its arcs are that vertex's); another one through a
// unit opened by one search serves every other search, and two such detours opened by
// different searches serve all.
// Every search then reaches each unit by a strictly shorter way than a left-out arc, so its
// distances and trees do not change.
void drop_dominated_arcs(const std::vector<int>& opened_by, double margin, SegmentUnits* units);

}  // namespace scbt
