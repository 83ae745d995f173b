// Stages 3-4: gap filling by Delaunay triangulation and the weighted graph (paper §III-B, III-C).
#pragma once

#include <vector>

#include "scbt/geometry/polygon.h"

namespace scbt {

struct GraphEdge {
  int u = 0;
  int v = 0;
  double length = 0.0;
  bool detected = false;
  // Edge weight (Eq. 3) = the gap length |B_G| it contributes: 0 for a detected segment, its
  // length for a generated (gap-filling) one.
  double weight = 0.0;
};

// Undirected graph whose vertices are segment endpoints and whose edges are the detected and
// generated segments. Adjacency is stored flat (CSR): the neighbours of vertex v are
// adjacency[adjacency_begin[v] .. adjacency_begin[v + 1]).
struct SegmentGraph {
  struct Incidence {
    int vertex;  // the neighbour
    int edge;    // index into `edges`
  };

  std::vector<Point> vertices;
  std::vector<GraphEdge> edges;
  // Indices into `edges` of the detected segments, in the order the segments were given.
  std::vector<int> detected_edges;
  std::vector<int> adjacency_begin;
  std::vector<Incidence> adjacency;

  int num_vertices() const { return static_cast<int>(vertices.size()); }
  int num_edges() const { return static_cast<int>(edges.size()); }
};

// Builds the graph from detected segments: endpoints that coincide exactly become one vertex,
// zero-length and repeated segments are dropped, the endpoints are Delaunay-triangulated and every
// triangulation edge that is not a detected segment becomes a generated edge. Edges: the detected
// ones in input order, then the generated ones ordered by (lower, higher) vertex id, u < v.
SegmentGraph build_segment_graph(const std::vector<Segment>& detected);
// The same into `graph`, reusing its buffers (a tracker calls it every frame).
void build_segment_graph(const std::vector<Segment>& detected, SegmentGraph* graph);

// Fills adjacency_begin/adjacency from vertices and edges.
void build_adjacency(SegmentGraph* graph);

}  // namespace scbt
