#include "scbt/graph/segment_graph.h"

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

// Appends the triangulation edges that are not detected (`detected_keys`, sorted edge_keys) as
// generated edges, ordered by (lower, higher) vertex id, so that the graph depends on the
// segments alone. `by_position` lists the vertices in lexicographic order.
void add_generated_edges(const std::vector<int>& by_position,
                         const std::vector<uint64_t>& detected_keys, SegmentGraph* graph) {
  const int n = graph->num_vertices();
  // The sites go in lexicographic order with the last vertex as the hint instead of through the
  // range constructor, which copies them twice and sorts them along a Hilbert curve: each new
  // site then lies beyond the hull next to the last one, and this stage takes about a third
  // less time (MarkCup 0.092 -> 0.062 ms). The triangulation does not depend on the order:
  // CGAL's Delaunay_triangulation_2 breaks cocircular ties by symbolic perturbation (tested
  // against the range constructor on grid points in segment_graph_test).
  Delaunay triangulation;
  Delaunay::Face_handle hint;
  for (int id : by_position) {
    const Point& p = graph->vertices[id];
    const Delaunay::Vertex_handle vertex = triangulation.insert(Kernel::Point_2(p.x, p.y), hint);
    vertex->info() = id;
    hint = vertex->face();
  }

  // Edges bucketed by their lower vertex (a counting sort) and each small bucket sorted: the
  // (lower, higher) order without sorting all keys, and detected edges skipped by one merge
  // with the sorted detected keys instead of a binary search per edge.
  thread_local std::vector<int> bucket_end, higher;
  thread_local std::vector<std::pair<int, int>> pairs;
  pairs.clear();
  bucket_end.assign(n + 1, 0);
  for (auto e = triangulation.finite_edges_begin(); e != triangulation.finite_edges_end(); ++e) {
    int u = e->first->vertex(Delaunay::cw(e->second))->info();
    int v = e->first->vertex(Delaunay::ccw(e->second))->info();
    if (u > v) std::swap(u, v);
    pairs.emplace_back(u, v);
    ++bucket_end[u + 1];
  }
  for (int u = 0; u < n; ++u) bucket_end[u + 1] += bucket_end[u];
  higher.resize(pairs.size());
  for (const auto& [u, v] : pairs) higher[bucket_end[u]++] = v;  // bucket_end[u]: u's end
  size_t next_key = 0;
  for (int u = 0, begin = 0; u < n; begin = bucket_end[u++]) {
    std::sort(higher.begin() + begin, higher.begin() + bucket_end[u]);
    for (int k = begin; k < bucket_end[u]; ++k) {
      const uint64_t key = edge_key(u, higher[k]);
      while (next_key < detected_keys.size() && detected_keys[next_key] < key) ++next_key;
      if (next_key < detected_keys.size() && detected_keys[next_key] == key) continue;
      GraphEdge edge;
      edge.u = u;
      edge.v = higher[k];
      edge.length = cv::norm(graph->vertices[edge.u] - graph->vertices[edge.v]);
      edge.weight = edge.length;
      graph->edges.push_back(edge);
    }
  }
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
  thread_local std::vector<int> next;
  next.assign(graph->adjacency_begin.begin(), graph->adjacency_begin.end() - 1);
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
  thread_local std::vector<int> first_of_edge, vertex_of;
  thread_local std::vector<uint64_t> keys;
  thread_local std::vector<std::pair<uint64_t, int>> keyed;

  // Endpoint k of segment i is occurrence 2i + k. Equal points become one vertex, numbered in
  // order of first appearance.
  const int occurrences = 2 * static_cast<int>(detected.size());
  auto endpoint = [&](int k) -> const Point& {
    return (k & 1) ? detected[k >> 1].b : detected[k >> 1].a;
  };
  // Sorted by (x, y, occurrence), a total order, so the result does not depend on the sort.
  // The coordinates are copied next to their occurrence: the comparisons then read one array
  // instead of reaching into the segments through the occurrence.
  struct Occurrence {
    double x, y;
    int k;
  };
  thread_local std::vector<Occurrence> sorted;
  sorted.resize(occurrences);
  for (int k = 0; k < occurrences; ++k) {
    const Point& p = endpoint(k);
    sorted[k] = {p.x, p.y, k};
  }
  std::sort(sorted.begin(), sorted.end(), [](const Occurrence& l, const Occurrence& r) {
    return l.x < r.x || (l.x == r.x && (l.y < r.y || (l.y == r.y && l.k < r.k)));
  });
  vertex_of.assign(occurrences, -1);
  // The vertices in lexicographic (x, y) order, the order they are triangulated in.
  thread_local std::vector<int> by_position;
  by_position.clear();
  // Each run of equal points is represented by its first (smallest) occurrence: mark every
  // member with -2 - representative, then number representatives in occurrence order.
  for (int start = 0; start < occurrences;) {
    int end = start + 1;
    while (end < occurrences && sorted[end].x == sorted[start].x &&
           sorted[end].y == sorted[start].y) {
      ++end;
    }
    for (int k = start + 1; k < end; ++k) vertex_of[sorted[k].k] = -2 - sorted[start].k;
    by_position.push_back(sorted[start].k);  // an occurrence, renumbered below
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
  for (int& v : by_position) v = vertex_of[v];

  // Detected edges in input order, dropping zero-length ones and repeats of an earlier one.
  keyed.clear();
  for (int i = 0; i < static_cast<int>(detected.size()); ++i) {
    const int u = vertex_of[2 * i], v = vertex_of[2 * i + 1];
    if (u != v) keyed.emplace_back(edge_key(u, v), i);
  }
  std::sort(keyed.begin(), keyed.end());
  keys.clear();
  first_of_edge.assign(detected.size(), 0);  // 1 marks the first segment of each edge
  for (size_t k = 0; k < keyed.size(); ++k) {
    if (k > 0 && keyed[k].first == keyed[k - 1].first) continue;
    keys.push_back(keyed[k].first);
    first_of_edge[keyed[k].second] = 1;
  }
  for (int i = 0; i < static_cast<int>(detected.size()); ++i) {
    if (!first_of_edge[i]) continue;
    graph.detected_edges.push_back(graph.num_edges());
    GraphEdge edge;
    edge.u = vertex_of[2 * i];
    edge.v = vertex_of[2 * i + 1];
    edge.length = cv::norm(detected[i].b - detected[i].a);
    edge.detected = true;
    graph.edges.push_back(edge);
  }

  if (graph.num_vertices() >= 2) add_generated_edges(by_position, keys, &graph);
  build_adjacency(&graph);
}

}  // namespace scbt
