// Single-source shortest paths (Dijkstra) on a SegmentGraph with one edge blocked.
#pragma once

#include <utility>
#include <vector>

#include "scbt/graph/segment_graph.h"

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
  // Vertices leave the queue in (distance, vertex id) order, so the result (ties included) does
  // not depend on how the queue is organised.
  bool before(int a, int b) const {
    return distance_[a] < distance_[b] || (distance_[a] == distance_[b] && a < b);
  }
  void sift_up(int position);
  void sift_down(int position);

  std::vector<double> distance_;
  std::vector<int> parent_edge_;
  std::vector<int> parent_vertex_;
  // Indexed 4-ary heap of vertices with decrease-key; heap_position_ is -1 outside the heap.
  std::vector<int> heap_;
  std::vector<int> heap_position_;
};

}  // namespace scbt
