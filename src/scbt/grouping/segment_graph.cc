#include "scbt/grouping/segment_graph.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <unordered_set>

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

struct PointLess {
  bool operator()(const Point& l, const Point& r) const {
    return l.x < r.x || (l.x == r.x && l.y < r.y);
  }
};

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
  std::map<Point, int, PointLess> vertex_of;
  auto vertex_id = [&](const Point& p) {
    auto [it, inserted] = vertex_of.try_emplace(p, graph.num_vertices());
    if (inserted) graph.vertices.push_back(p);
    return it->second;
  };

  std::unordered_set<uint64_t> present;
  for (const Segment& s : detected) {
    const int u = vertex_id(s.a);
    const int v = vertex_id(s.b);
    if (u == v || !present.insert(edge_key(u, v)).second) continue;
    graph.detected_edges.push_back(graph.num_edges());
    GraphEdge edge;
    edge.u = u;
    edge.v = v;
    edge.length = cv::norm(s.b - s.a);
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
    for (auto e = triangulation.finite_edges_begin(); e != triangulation.finite_edges_end(); ++e) {
      const int u = e->first->vertex(Delaunay::cw(e->second))->info();
      const int v = e->first->vertex(Delaunay::ccw(e->second))->info();
      if (!present.insert(edge_key(u, v)).second) continue;
      GraphEdge edge;
      edge.u = u;
      edge.v = v;
      edge.length = cv::norm(graph.vertices[u] - graph.vertices[v]);
      edge.weight = edge.length;
      graph.edges.push_back(edge);
    }
  }
  build_adjacency(&graph);
  return graph;
}

}  // namespace scbt
