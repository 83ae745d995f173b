#include "scbt/reference/bdsp_generic.h"

#include <algorithm>
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>
#include <boost/graph/filtered_graph.hpp>
#include <cmath>
#include <limits>

namespace scbt {
namespace {

using EdgeProperties =
    boost::property<boost::edge_weight_t, double, boost::property<boost::edge_index_t, int>>;
using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS,
                                    boost::no_property, EdgeProperties>;
using Vertex = boost::graph_traits<Graph>::vertex_descriptor;

// Hides one edge (by its index in SegmentGraph::edges).
struct NotBlocked {
  NotBlocked() = default;
  NotBlocked(const Graph* graph, int blocked) : graph(graph), blocked(blocked) {}
  template <typename Edge>
  bool operator()(const Edge& e) const {
    return boost::get(boost::edge_index, *graph, e) != blocked;
  }
  const Graph* graph = nullptr;
  int blocked = -1;
};

struct Tree {
  std::vector<Vertex> parent;
  std::vector<double> distance;
  bool reached(int v) const { return std::isfinite(distance[v]); }
};

void shortest_paths(const Graph& graph, int source, int blocked, Tree* tree) {
  const size_t n = boost::num_vertices(graph);
  tree->parent.assign(n, 0);
  tree->distance.assign(n, std::numeric_limits<double>::infinity());
  const boost::filtered_graph<Graph, NotBlocked> view(graph, NotBlocked(&graph, blocked));
  boost::dijkstra_shortest_paths(
      view, static_cast<Vertex>(source),
      boost::predecessor_map(boost::make_iterator_property_map(
                                 tree->parent.begin(), boost::get(boost::vertex_index, graph)))
          .distance_map(boost::make_iterator_property_map(tree->distance.begin(),
                                                          boost::get(boost::vertex_index, graph)))
          .weight_map(boost::get(boost::edge_weight, graph)));
}

double cycle_area(const SegmentGraph& graph, const std::vector<int>& cycle) {
  double twice_area = 0.0;
  const size_t n = cycle.size();
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point& p = graph.vertices[cycle[j]];
    const Point& q = graph.vertices[cycle[i]];
    twice_area += p.x * q.y - q.x * p.y;
  }
  return 0.5 * std::abs(twice_area);
}

}  // namespace

std::vector<CycleCandidate> search_cycle_candidates_generic(const SegmentGraph& graph,
                                                            const BdspOptions& options) {
  options.check();
  const int n = graph.num_vertices();
  Graph g(n);
  for (int e = 0; e < graph.num_edges(); ++e) {
    boost::add_edge(graph.edges[e].u, graph.edges[e].v, EdgeProperties(graph.edges[e].weight, e),
                    g);
  }

  std::vector<CycleCandidate> candidates;
  std::vector<int> meeting_seen(n, -1);
  std::vector<char> on_second(n, 0);
  std::vector<int> path;
  Tree first, second;
  const int num_detected = static_cast<int>(graph.detected_edges.size());
  for (int i = 0; i < num_detected; i += options.seed_stride) {
    const int seed = graph.detected_edges[i];
    const int s1 = graph.edges[seed].u;
    const int s2 = graph.edges[seed].v;
    shortest_paths(g, s1, seed, &first);
    shortest_paths(g, s2, seed, &second);
    for (int j = 0; j < num_detected; ++j) {
      if (j == i) continue;
      const int third = graph.edges[graph.detected_edges[j]].u;
      if (!first.reached(third) || !second.reached(third)) continue;
      // Mark the path third -> s2, then walk s1 -> third to the first marked vertex.
      std::fill(on_second.begin(), on_second.end(), 0);
      for (int v = third;; v = static_cast<int>(second.parent[v])) {
        on_second[v] = 1;
        if (v == s2) break;
      }
      path.clear();
      for (int v = third;; v = static_cast<int>(first.parent[v])) {
        path.push_back(v);
        if (v == s1) break;
      }
      std::reverse(path.begin(), path.end());
      size_t meet = 0;
      while (!on_second[path[meet]]) ++meet;
      const int meeting = path[meet];
      if (meeting_seen[meeting] == i) continue;
      meeting_seen[meeting] = i;

      CycleCandidate candidate;
      candidate.seed_edge = seed;
      candidate.vertices.assign(path.begin(), path.begin() + meet + 1);
      for (int v = meeting; v != s2; v = static_cast<int>(second.parent[v])) {
        candidate.vertices.push_back(static_cast<int>(second.parent[v]));
      }
      if (candidate.vertices.size() < 3) continue;
      candidate.gap_length = first.distance[meeting] + second.distance[meeting];
      candidate.area = cycle_area(graph, candidate.vertices);
      candidates.push_back(std::move(candidate));
    }
  }
  return candidates;
}

}  // namespace scbt
