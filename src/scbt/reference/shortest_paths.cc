#include "scbt/reference/shortest_paths.h"

#include <algorithm>
#include <functional>
#include <limits>

namespace scbt {

void ShortestPaths::sift_up(int position) {
  const int v = heap_[position];
  while (position > 0) {
    const int parent = (position - 1) / 4;
    if (!before(v, heap_[parent])) break;
    heap_[position] = heap_[parent];
    heap_position_[heap_[position]] = position;
    position = parent;
  }
  heap_[position] = v;
  heap_position_[v] = position;
}

void ShortestPaths::sift_down(int position) {
  const int size = static_cast<int>(heap_.size());
  const int v = heap_[position];
  for (;;) {
    const int first = 4 * position + 1;
    if (first >= size) break;
    int best = first;
    const int last = std::min(first + 4, size);
    for (int c = first + 1; c < last; ++c) {
      if (before(heap_[c], heap_[best])) best = c;
    }
    if (!before(heap_[best], v)) break;
    heap_[position] = heap_[best];
    heap_position_[heap_[position]] = position;
    position = best;
  }
  heap_[position] = v;
  heap_position_[v] = position;
}

void ShortestPaths::run(const SegmentGraph& graph, int source, int blocked_edge) {
  const int n = graph.num_vertices();
  distance_.assign(n, std::numeric_limits<double>::infinity());
  parent_edge_.assign(n, kUnreached);
  parent_vertex_.assign(n, -1);
  heap_position_.assign(n, -1);
  heap_.clear();

  distance_[source] = 0.0;
  parent_edge_[source] = -1;
  heap_.push_back(source);
  heap_position_[source] = 0;
  const SegmentGraph::Incidence* adjacency = graph.adjacency.data();
  const GraphEdge* edges = graph.edges.data();
  while (!heap_.empty()) {
    const int u = heap_.front();
    heap_position_[u] = -1;
    const int last = heap_.back();
    heap_.pop_back();
    if (!heap_.empty()) {
      heap_.front() = last;
      sift_down(0);
    }
    const double d = distance_[u];
    for (int k = graph.adjacency_begin[u]; k < graph.adjacency_begin[u + 1]; ++k) {
      const SegmentGraph::Incidence& next = adjacency[k];
      if (next.edge == blocked_edge) continue;
      const double candidate = d + edges[next.edge].weight;
      const int w = next.vertex;
      if (candidate < distance_[w]) {
        distance_[w] = candidate;
        parent_edge_[w] = next.edge;
        parent_vertex_[w] = u;
        if (heap_position_[w] < 0) {
          heap_.push_back(w);
          sift_up(static_cast<int>(heap_.size()) - 1);
        } else {
          sift_up(heap_position_[w]);
        }
      }
    }
  }
}

}  // namespace scbt
