// Single-source shortest paths (Dijkstra) on a SegmentGraph with one edge blocked.
#pragma once

#include <utility>
#include <vector>

#include "scbt/grouping/segment_graph.h"

namespace scbt {

// Hand-written rather than Boost.Graph: BDSP runs two searches per seed on graphs of ~100
// vertices, so the per-call set-up of a generic graph library dominates; this keeps flat arrays
// and one heap buffer that are reused across calls (no allocation once warmed up).
class ShortestPaths {
 public:
  // Distances are exact doubles (the authors' code truncated them to int).
  void run(const SegmentGraph& graph, int source, int blocked_edge);

  bool reached(int v) const { return parent_edge_[v] != kUnreached; }
  double distance(int v) const { return distance_[v]; }
  // The edge by which v is reached on its shortest path; -1 for the source.
  int parent_edge(int v) const { return parent_edge_[v]; }
  int parent_vertex(int v) const { return parent_vertex_[v]; }

 private:
  static constexpr int kUnreached = -2;
  std::vector<double> distance_;
  std::vector<int> parent_edge_;
  std::vector<int> parent_vertex_;
  std::vector<std::pair<double, int>> heap_;
};

}  // namespace scbt
