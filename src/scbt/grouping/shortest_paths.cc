#include "scbt/grouping/shortest_paths.h"

#include <algorithm>
#include <functional>
#include <limits>

namespace scbt {

void ShortestPaths::run(const SegmentGraph& graph, int source, int blocked_edge) {
  const int n = graph.num_vertices();
  distance_.assign(n, std::numeric_limits<double>::infinity());
  parent_edge_.assign(n, kUnreached);
  parent_vertex_.assign(n, -1);
  heap_.clear();

  // Lazy-deletion binary heap: stale entries are skipped when popped.
  auto push = [&](double d, int v) {
    heap_.emplace_back(d, v);
    std::push_heap(heap_.begin(), heap_.end(), std::greater<>());
  };
  distance_[source] = 0.0;
  parent_edge_[source] = -1;
  push(0.0, source);
  while (!heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end(), std::greater<>());
    const auto [d, u] = heap_.back();
    heap_.pop_back();
    if (d > distance_[u]) continue;
    for (int k = graph.adjacency_begin[u]; k < graph.adjacency_begin[u + 1]; ++k) {
      const SegmentGraph::Incidence& next = graph.adjacency[k];
      if (next.edge == blocked_edge) continue;
      const double candidate = d + graph.edges[next.edge].weight;
      if (candidate < distance_[next.vertex]) {
        distance_[next.vertex] = candidate;
        parent_edge_[next.vertex] = next.edge;
        parent_vertex_[next.vertex] = u;
        push(candidate, next.vertex);
      }
    }
  }
}

}  // namespace scbt
