#include "scbt/grouping/segment_graph.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cstdint>

namespace scbt {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using DataStructure = CGAL::Triangulation_data_structure_2<VertexBase>;
using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, DataStructure>;

uint64_t edge_key(int u, int v) {
  if (u > v) std::swap(u, v);
  return (static_cast<uint64_t>(static_cast<uint32_t>(u)) << 32) | static_cast<uint32_t>(v);
}

}  // namespace

void build_adjacency(SegmentGraph* graph) {
  const int n = graph->num_vertices();
  graph->adjacency_begin.assign(n + 1, 0);
  for (const GraphEdge& e : graph->edges) {
    ++graph->adjacency_begin[e.u + 1];
    ++graph->adjacency_begin[e.v + 1];
  }
  for (int v = 0; v < n; ++v) graph->adjacency_begin[v + 1] += graph->adjacency_begin[v];
  graph->adjacency.resize(graph->adjacency_begin[n]);
  std::vector<int> next(graph->adjacency_begin.begin(), graph->adjacency_begin.end() - 1);
  for (int i = 0; i < graph->num_edges(); ++i) {
    const GraphEdge& e = graph->edges[i];
    graph->adjacency[next[e.u]++] = {e.v, i};
    graph->adjacency[next[e.v]++] = {e.u, i};
  }
}

SegmentGraph build_segment_graph(const std::vector<Segment>& detected) {
  SegmentGraph graph;
  build_segment_graph(detected, &graph);
  return graph;
}

void build_segment_graph(const std::vector<Segment>& detected, SegmentGraph* graph_out) {
  SegmentGraph& graph = *graph_out;
  graph.vertices.clear();
  graph.edges.clear();
  graph.detected_edges.clear();
  // Sorting flat arrays instead of a std::map of points and a hash set of edges: the same graph,
  // with a few reused buffers instead of a node allocation per endpoint and per edge (the map
  // and set were half of this stage's time).
  thread_local std::vector<int> order, vertex_of;
  thread_local std::vector<uint64_t> keys;
  thread_local std::vector<std::pair<uint64_t, int>> keyed;

  // Endpoint k of segment i is occurrence 2i + k. Equal points become one vertex, numbered in
  // order of first appearance.
  const int occurrences = 2 * static_cast<int>(detected.size());
  auto endpoint = [&](int k) -> const Point& {
    return (k & 1) ? detected[k >> 1].b : detected[k >> 1].a;
  };
  order.resize(occurrences);
  for (int k = 0; k < occurrences; ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](int l, int r) {
    const Point &p = endpoint(l), &q = endpoint(r);
    return p.x < q.x || (p.x == q.x && (p.y < q.y || (p.y == q.y && l < r)));
  });
  vertex_of.assign(occurrences, -1);
  // Each run of equal points is represented by its first (smallest) occurrence: mark every
  // member with -2 - representative, then number representatives in occurrence order.
  for (int start = 0; start < occurrences;) {
    int end = start + 1;
    while (end < occurrences && endpoint(order[end]) == endpoint(order[start])) ++end;
    for (int k = start + 1; k < end; ++k) vertex_of[order[k]] = -2 - order[start];
    start = end;
  }
  for (int k = 0; k < occurrences; ++k) {
    if (vertex_of[k] == -1) {
      vertex_of[k] = graph.num_vertices();
      graph.vertices.push_back(endpoint(k));
    } else {
      vertex_of[k] = vertex_of[-2 - vertex_of[k]];
    }
  }

  // Detected edges in input order, dropping zero-length ones and repeats of an earlier one.
  keyed.clear();
  for (int i = 0; i < static_cast<int>(detected.size()); ++i) {
    const int u = vertex_of[2 * i], v = vertex_of[2 * i + 1];
    if (u != v) keyed.emplace_back(edge_key(u, v), i);
  }
  std::sort(keyed.begin(), keyed.end());
  keys.clear();
  order.assign(detected.size(), 0);  // reused: 1 marks the first segment of each edge
  for (size_t k = 0; k < keyed.size(); ++k) {
    if (k > 0 && keyed[k].first == keyed[k - 1].first) continue;
    keys.push_back(keyed[k].first);
    order[keyed[k].second] = 1;
  }
  for (int i = 0; i < static_cast<int>(detected.size()); ++i) {
    if (!order[i]) continue;
    graph.detected_edges.push_back(graph.num_edges());
    GraphEdge edge;
    edge.u = vertex_of[2 * i];
    edge.v = vertex_of[2 * i + 1];
    edge.length = cv::norm(detected[i].b - detected[i].a);
    edge.detected = true;
    graph.edges.push_back(edge);
  }

  if (graph.num_vertices() >= 2) {
    std::vector<std::pair<Kernel::Point_2, int>> sites;
    sites.reserve(graph.vertices.size());
    for (int i = 0; i < graph.num_vertices(); ++i) {
      sites.emplace_back(Kernel::Point_2(graph.vertices[i].x, graph.vertices[i].y), i);
    }
    Delaunay triangulation(sites.begin(), sites.end());
    // Triangulation edges are distinct; those that are detected segments are already in. CGAL
    // inserts the sites in a randomised order, so its edge order differs from call to call;
    // sorting the generated edges makes the graph (and the tie-breaks of the searches on it)
    // depend on the segments alone.
    keyed.clear();
    for (auto e = triangulation.finite_edges_begin(); e != triangulation.finite_edges_end(); ++e) {
      const int u = e->first->vertex(Delaunay::cw(e->second))->info();
      const int v = e->first->vertex(Delaunay::ccw(e->second))->info();
      const uint64_t key = edge_key(u, v);
      if (!std::binary_search(keys.begin(), keys.end(), key)) keyed.emplace_back(key, 0);
    }
    std::sort(keyed.begin(), keyed.end());
    for (const auto& [key, unused] : keyed) {
      GraphEdge edge;
      edge.u = static_cast<int>(key >> 32);
      edge.v = static_cast<int>(key & 0xffffffffu);
      edge.length = cv::norm(graph.vertices[edge.u] - graph.vertices[edge.v]);
      edge.weight = edge.length;
      graph.edges.push_back(edge);
    }
  }
  build_adjacency(&graph);
}

}  // namespace scbt
