// Dijkstra with a blocked edge against Bellman-Ford on random small graphs.
#include "scbt/reference/shortest_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include "scbt/testing/random_graphs.h"

namespace scbt {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

GraphEdge make_edge(int u, int v, double weight, bool detected) {
  GraphEdge e;
  e.u = u;
  e.v = v;
  e.length = weight;
  e.detected = detected;
  e.weight = weight;
  return e;
}

// Random multigraph of n vertices and m edges; weights are 0 (detected) or random lengths.
SegmentGraph random_graph(std::mt19937& rng, int n, int m) {
  return random_multigraph(rng, n, m, [](std::mt19937& r) {
    return std::uniform_real_distribution<double>(0.0, 50.0)(r);
  });
}

std::vector<double> bellman_ford(const SegmentGraph& graph, int source, int blocked) {
  std::vector<double> d(graph.num_vertices(), kInf);
  d[source] = 0.0;
  for (int round = 0; round < graph.num_vertices(); ++round) {
    bool changed = false;
    for (int i = 0; i < graph.num_edges(); ++i) {
      if (i == blocked) continue;
      const GraphEdge& e = graph.edges[i];
      if (d[e.u] + e.weight < d[e.v]) {
        d[e.v] = d[e.u] + e.weight;
        changed = true;
      }
      if (d[e.v] + e.weight < d[e.u]) {
        d[e.u] = d[e.v] + e.weight;
        changed = true;
      }
    }
    if (!changed) break;
  }
  return d;
}

class ShortestPathsProperty : public ::testing::TestWithParam<unsigned> {};

TEST_P(ShortestPathsProperty, MatchesBellmanFordAndParentsSumToDistance) {
  std::mt19937 rng(GetParam() * 13u + 5u);
  std::uniform_int_distribution<int> size(2, 30);
  const int n = size(rng);
  std::uniform_int_distribution<int> edges(1, 3 * n);
  const SegmentGraph graph = random_graph(rng, n, edges(rng));
  std::uniform_int_distribution<int> vertex(0, n - 1);
  std::uniform_int_distribution<int> edge(-1, graph.num_edges() - 1);

  ShortestPaths paths;  // reused across runs, as BDSP does
  for (int run = 0; run < 5; ++run) {
    const int source = vertex(rng);
    const int blocked = edge(rng);
    paths.run(graph, source, blocked);
    const std::vector<double> expected = bellman_ford(graph, source, blocked);
    EXPECT_EQ(paths.parent_edge(source), -1);
    EXPECT_EQ(paths.distance(source), 0.0);
    for (int v = 0; v < n; ++v) {
      SCOPED_TRACE("vertex " + std::to_string(v));
      ASSERT_EQ(paths.reached(v), std::isfinite(expected[v]));
      if (!paths.reached(v)) continue;
      EXPECT_NEAR(paths.distance(v), expected[v], 1e-9);
      // Walk the parent chain back to the source, summing weights; it never uses the blocked
      // edge and each step follows a real edge.
      double sum = 0.0;
      int steps = 0;
      for (int w = v; w != source; w = paths.parent_vertex(w)) {
        ASSERT_LT(steps++, n) << "parent chain loops";
        const int e = paths.parent_edge(w);
        ASSERT_GE(e, 0);
        EXPECT_NE(e, blocked);
        const GraphEdge& edge_w = graph.edges[e];
        const int p = paths.parent_vertex(w);
        EXPECT_TRUE((edge_w.u == w && edge_w.v == p) || (edge_w.v == w && edge_w.u == p));
        sum += edge_w.weight;
      }
      EXPECT_NEAR(sum, paths.distance(v), 1e-9);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Seeds, ShortestPathsProperty, ::testing::Range(0u, 150u));

SegmentGraph triangle() {
  // 0 -1- 1 -1- 2, and a direct 0-2 edge of weight 0 (detected).
  SegmentGraph graph;
  graph.vertices = {{0, 0}, {1, 0}, {2, 0}};
  graph.edges.resize(3);
  graph.edges[0] = make_edge(0, 1, 1.0, false);
  graph.edges[1] = make_edge(1, 2, 1.0, false);
  graph.edges[2] = make_edge(0, 2, 0.0, true);
  build_adjacency(&graph);
  return graph;
}

TEST(ShortestPaths, BlockedEdgeIsNotUsed) {
  const SegmentGraph graph = triangle();
  ShortestPaths paths;
  paths.run(graph, 0, -1);
  EXPECT_EQ(paths.distance(2), 0.0);
  EXPECT_EQ(paths.parent_edge(2), 2);
  paths.run(graph, 0, 2);
  EXPECT_EQ(paths.distance(2), 2.0);
  EXPECT_EQ(paths.parent_vertex(2), 1);
  EXPECT_EQ(paths.parent_edge(2), 1);
  // Blocking the only edge to a vertex leaves it unreached.
  paths.run(graph, 1, 0);
  EXPECT_TRUE(paths.reached(0));  // through 2
  EXPECT_EQ(paths.distance(0), 1.0);
}

TEST(ShortestPaths, UnreachableVertex) {
  SegmentGraph graph;
  graph.vertices = {{0, 0}, {1, 0}, {5, 5}};
  graph.edges.resize(1);
  graph.edges[0] = make_edge(0, 1, 1.0, false);
  build_adjacency(&graph);
  ShortestPaths paths;
  paths.run(graph, 0, -1);
  EXPECT_TRUE(paths.reached(1));
  EXPECT_FALSE(paths.reached(2));
  EXPECT_TRUE(std::isinf(paths.distance(2)));
  paths.run(graph, 0, 0);
  EXPECT_FALSE(paths.reached(1));
}

// The textbook lazy-deletion binary-heap Dijkstra (the first implementation): the optimised
// queue must give the same parents, ties included, since BDSP's candidates follow them.
struct LazyDijkstra {
  std::vector<double> distance;
  std::vector<int> parent_edge, parent_vertex;
  void run(const SegmentGraph& graph, int source, int blocked) {
    const int n = graph.num_vertices();
    distance.assign(n, kInf);
    parent_edge.assign(n, -2);
    parent_vertex.assign(n, -1);
    std::vector<std::pair<double, int>> heap;
    distance[source] = 0.0;
    parent_edge[source] = -1;
    heap.emplace_back(0.0, source);
    while (!heap.empty()) {
      std::pop_heap(heap.begin(), heap.end(), std::greater<>());
      const auto [d, u] = heap.back();
      heap.pop_back();
      if (d > distance[u]) continue;
      for (int k = graph.adjacency_begin[u]; k < graph.adjacency_begin[u + 1]; ++k) {
        const SegmentGraph::Incidence& next = graph.adjacency[k];
        if (next.edge == blocked) continue;
        const double candidate = d + graph.edges[next.edge].weight;
        if (candidate < distance[next.vertex]) {
          distance[next.vertex] = candidate;
          parent_edge[next.vertex] = next.edge;
          parent_vertex[next.vertex] = u;
          heap.emplace_back(candidate, next.vertex);
          std::push_heap(heap.begin(), heap.end(), std::greater<>());
        }
      }
    }
  }
};

// Integer weights (many equal path lengths) and zero-weight detected edges make ties common.
TEST(ShortestPaths, SameParentsAsLazyHeapDijkstraWithTies) {
  std::mt19937 rng(77);
  ShortestPaths paths;  // reused across graphs of different sizes
  LazyDijkstra reference;
  for (int trial = 0; trial < 300; ++trial) {
    std::uniform_int_distribution<int> size(2, 120);
    const int n = size(rng);
    SegmentGraph graph = random_graph(rng, n, 3 * n);
    std::uniform_int_distribution<int> small(0, 4);
    for (GraphEdge& e : graph.edges) e.weight = e.detected ? 0.0 : small(rng);
    const int source = std::uniform_int_distribution<int>(0, n - 1)(rng);
    const int blocked = std::uniform_int_distribution<int>(-1, graph.num_edges() - 1)(rng);
    paths.run(graph, source, blocked);
    reference.run(graph, source, blocked);
    for (int v = 0; v < n; ++v) {
      ASSERT_EQ(paths.reached(v), reference.parent_edge[v] != -2) << trial << " v " << v;
      if (!paths.reached(v)) continue;
      EXPECT_EQ(paths.distance(v), reference.distance[v]) << trial << " v " << v;
      EXPECT_EQ(paths.parent_edge(v), reference.parent_edge[v]) << trial << " v " << v;
      EXPECT_EQ(paths.parent_vertex(v), reference.parent_vertex[v]) << trial << " v " << v;
    }
  }
}

}  // namespace
}  // namespace scbt
