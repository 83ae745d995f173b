// Structural properties of the gap-filled segment graph over random non-crossing segment sets.
#include "scbt/graph/segment_graph.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <queue>
#include <random>
#include <set>
#include <utility>

namespace scbt {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Proper crossing by the exact-sign cross products, written here independently of polygon.cc.
double cross(const Point& o, const Point& a, const Point& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}
bool properly_cross(const Point& p1, const Point& p2, const Point& q1, const Point& q2) {
  const double d1 = cross(p1, p2, q1), d2 = cross(p1, p2, q2);
  const double d3 = cross(q1, q2, p1), d4 = cross(q1, q2, p2);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

// Short random segments, each rejected if it crosses an earlier one. About a third start at an
// endpoint of an earlier segment, so that chains (shared vertices) occur.
std::vector<Segment> random_segments(std::mt19937& rng, int count) {
  std::uniform_real_distribution<double> pos(0.0, 400.0), len(5.0, 60.0), angle(-kPi, kPi);
  std::uniform_int_distribution<int> coin(0, 2);
  std::vector<Segment> segments;
  int attempts = 0;
  while (static_cast<int>(segments.size()) < count && attempts++ < 100 * count) {
    Point a(pos(rng), pos(rng));
    if (!segments.empty() && coin(rng) == 0) {
      std::uniform_int_distribution<size_t> pick(0, segments.size() - 1);
      const Segment& s = segments[pick(rng)];
      a = coin(rng) == 0 ? s.a : s.b;
    }
    const double t = angle(rng);
    const Segment candidate{a, a + Point(std::cos(t), std::sin(t)) * len(rng)};
    bool ok = true;
    for (const Segment& s : segments) {
      if (properly_cross(candidate.a, candidate.b, s.a, s.b)) {
        ok = false;
        break;
      }
    }
    if (ok) segments.push_back(candidate);
  }
  return segments;
}

size_t count_distinct(const std::vector<Segment>& segments) {
  std::set<std::pair<double, double>> points;
  for (const Segment& s : segments) {
    points.emplace(s.a.x, s.a.y);
    points.emplace(s.b.x, s.b.y);
  }
  return points.size();
}

void expect_adjacency_consistent(const SegmentGraph& graph) {
  const int n = graph.num_vertices();
  ASSERT_EQ(graph.adjacency_begin.size(), static_cast<size_t>(n + 1));
  EXPECT_EQ(graph.adjacency_begin.front(), 0);
  EXPECT_EQ(graph.adjacency_begin.back(), 2 * graph.num_edges());
  ASSERT_EQ(graph.adjacency.size(), static_cast<size_t>(2 * graph.num_edges()));
  std::vector<int> seen(graph.num_edges(), 0);
  for (int v = 0; v < n; ++v) {
    ASSERT_LE(graph.adjacency_begin[v], graph.adjacency_begin[v + 1]);
    for (int k = graph.adjacency_begin[v]; k < graph.adjacency_begin[v + 1]; ++k) {
      const SegmentGraph::Incidence& inc = graph.adjacency[k];
      ASSERT_GE(inc.edge, 0);
      ASSERT_LT(inc.edge, graph.num_edges());
      const GraphEdge& e = graph.edges[inc.edge];
      // The incidence is listed at one endpoint and names the other.
      EXPECT_TRUE((e.u == v && e.v == inc.vertex) || (e.v == v && e.u == inc.vertex));
      ++seen[inc.edge];
    }
  }
  for (int i = 0; i < graph.num_edges(); ++i) EXPECT_EQ(seen[i], 2) << "edge " << i;
}

bool connected(const SegmentGraph& graph) {
  if (graph.num_vertices() == 0) return true;
  std::vector<bool> visited(graph.num_vertices(), false);
  std::queue<int> queue;
  queue.push(0);
  visited[0] = true;
  int count = 1;
  while (!queue.empty()) {
    const int u = queue.front();
    queue.pop();
    for (const GraphEdge& e : graph.edges) {  // deliberately not via the CSR under test
      int w = -1;
      if (e.u == u) w = e.v;
      if (e.v == u) w = e.u;
      if (w >= 0 && !visited[w]) {
        visited[w] = true;
        ++count;
        queue.push(w);
      }
    }
  }
  return count == graph.num_vertices();
}

class SegmentGraphProperty : public ::testing::TestWithParam<unsigned> {};

TEST_P(SegmentGraphProperty, StructureOfRandomNonCrossingSegments) {
  std::mt19937 rng(GetParam() * 97u + 3u);
  std::uniform_int_distribution<int> count(2, 40);
  const std::vector<Segment> segments = random_segments(rng, count(rng));
  ASSERT_GE(segments.size(), 2u);
  const SegmentGraph graph = build_segment_graph(segments);

  EXPECT_EQ(static_cast<size_t>(graph.num_vertices()), count_distinct(segments));
  // Every vertex is an endpoint, and every endpoint maps to exactly one vertex.
  std::map<std::pair<double, double>, int> id;
  for (int v = 0; v < graph.num_vertices(); ++v) {
    EXPECT_TRUE(id.emplace(std::make_pair(graph.vertices[v].x, graph.vertices[v].y), v).second);
  }

  std::set<std::pair<int, int>> undirected;
  int num_generated = 0;
  for (const GraphEdge& e : graph.edges) {
    ASSERT_GE(e.u, 0);
    ASSERT_LT(e.u, graph.num_vertices());
    ASSERT_GE(e.v, 0);
    ASSERT_LT(e.v, graph.num_vertices());
    EXPECT_NE(e.u, e.v) << "self loop";
    EXPECT_TRUE(undirected.emplace(std::min(e.u, e.v), std::max(e.u, e.v)).second)
        << "duplicate edge " << e.u << "-" << e.v;
    const double length = cv::norm(graph.vertices[e.u] - graph.vertices[e.v]);
    EXPECT_NEAR(e.length, length, 1e-9);
    if (e.detected) {
      EXPECT_EQ(e.weight, 0.0);
    } else {
      EXPECT_NEAR(e.weight, length, 1e-9);
      ++num_generated;
    }
  }

  // Every detected segment is present, in input order, as a detected edge of weight 0.
  ASSERT_EQ(graph.detected_edges.size(), segments.size());
  for (size_t k = 0; k < segments.size(); ++k) {
    const GraphEdge& e = graph.edges[graph.detected_edges[k]];
    EXPECT_TRUE(e.detected);
    EXPECT_EQ(e.weight, 0.0);
    const int a = id.at({segments[k].a.x, segments[k].a.y});
    const int b = id.at({segments[k].b.x, segments[k].b.y});
    EXPECT_TRUE((e.u == a && e.v == b) || (e.u == b && e.v == a));
  }
  const int num_detected_flags = static_cast<int>(std::count_if(
      graph.edges.begin(), graph.edges.end(), [](const GraphEdge& e) { return e.detected; }));
  EXPECT_EQ(num_detected_flags, static_cast<int>(segments.size()));

  // Generated edges are Delaunay edges: a plane graph, at most 3V - 6 of them (V >= 3).
  for (int i = 0; i < graph.num_edges(); ++i) {
    if (graph.edges[i].detected) continue;
    for (int j = i + 1; j < graph.num_edges(); ++j) {
      if (graph.edges[j].detected) continue;
      const GraphEdge& e = graph.edges[i];
      const GraphEdge& f = graph.edges[j];
      EXPECT_FALSE(properly_cross(graph.vertices[e.u], graph.vertices[e.v], graph.vertices[f.u],
                                  graph.vertices[f.v]))
          << "generated edges " << i << " and " << j << " cross";
    }
  }
  if (graph.num_vertices() >= 3) {
    EXPECT_LE(num_generated, 3 * graph.num_vertices() - 6);
  }
  EXPECT_GT(num_generated, 0);

  EXPECT_TRUE(connected(graph));
  expect_adjacency_consistent(graph);
}

INSTANTIATE_TEST_SUITE_P(Seeds, SegmentGraphProperty, ::testing::Range(0u, 100u));

TEST(SegmentGraph, MergesCoincidentEndpointsAndDropsDegenerateSegments) {
  const std::vector<Segment> segments{
      {{0, 0}, {10, 0}},     // 0
      {{10, 0}, {10, 10}},   // shares (10, 0)
      {{10, 0}, {0, 0}},     // repeat of the first, reversed: dropped
      {{0, 0}, {10, 0}},     // repeat of the first: dropped
      {{20, 20}, {20, 20}},  // zero length: dropped
      {{10, 10}, {0, 10}},
  };
  const SegmentGraph graph = build_segment_graph(segments);
  ASSERT_EQ(graph.detected_edges.size(), 3u);
  // (0,0), (10,0), (10,10), (0,10) are shared by the three kept segments.
  const GraphEdge& first = graph.edges[graph.detected_edges[0]];
  const GraphEdge& second = graph.edges[graph.detected_edges[1]];
  const GraphEdge& third = graph.edges[graph.detected_edges[2]];
  EXPECT_EQ(graph.vertices[first.u], Point(0, 0));
  EXPECT_EQ(graph.vertices[first.v], Point(10, 0));
  EXPECT_EQ(second.u, first.v);  // merged vertex
  EXPECT_EQ(third.u, second.v);
  EXPECT_EQ(graph.vertices[third.v], Point(0, 10));
  for (const GraphEdge& e : graph.edges) EXPECT_NE(e.u, e.v);
  // The fourth side of the square is a generated edge of weight 10.
  bool found_gap = false;
  for (const GraphEdge& e : graph.edges) {
    if (std::min(e.u, e.v) == first.u && std::max(e.u, e.v) == third.v) {
      found_gap = true;
      EXPECT_FALSE(e.detected);
      EXPECT_DOUBLE_EQ(e.weight, 10.0);
    }
  }
  EXPECT_TRUE(found_gap);
  expect_adjacency_consistent(graph);
}

TEST(SegmentGraph, EmptyAndSingleSegment) {
  const SegmentGraph empty = build_segment_graph({});
  EXPECT_EQ(empty.num_vertices(), 0);
  EXPECT_EQ(empty.num_edges(), 0);
  ASSERT_EQ(empty.adjacency_begin.size(), 1u);

  const SegmentGraph one = build_segment_graph({{{1, 2}, {3, 4}}});
  EXPECT_EQ(one.num_vertices(), 2);
  ASSERT_EQ(one.num_edges(), 1);  // the Delaunay edge coincides with the segment
  EXPECT_TRUE(one.edges[0].detected);
  expect_adjacency_consistent(one);
}

TEST(SegmentGraph, CollinearEndpointsStayConnected) {
  // Three collinear segments with gaps: the triangulation degenerates to a chain.
  const SegmentGraph graph =
      build_segment_graph({{{0, 0}, {10, 0}}, {{20, 0}, {30, 0}}, {{40, 0}, {50, 0}}});
  EXPECT_EQ(graph.num_vertices(), 6);
  EXPECT_EQ(graph.num_edges(), 5);
  EXPECT_TRUE(connected(graph));
  double gap = 0.0;
  for (const GraphEdge& e : graph.edges) gap += e.weight;
  EXPECT_DOUBLE_EQ(gap, 20.0);
}

TEST(BuildAdjacency, HandMadeGraph) {
  SegmentGraph graph;
  graph.vertices = {{0, 0}, {1, 0}, {2, 0}, {3, 0}};
  graph.edges.resize(3);
  graph.edges[0].u = 0;
  graph.edges[0].v = 1;
  graph.edges[1].u = 2;
  graph.edges[1].v = 1;
  graph.edges[2].u = 0;
  graph.edges[2].v = 2;
  build_adjacency(&graph);
  expect_adjacency_consistent(graph);
  EXPECT_EQ(graph.adjacency_begin, (std::vector<int>{0, 2, 4, 6, 6}));  // vertex 3 isolated
}

// The vertex numbering and detected edges written plainly: a map of points in first-appearance
// order and a set of undirected vertex pairs.
struct PlainVertices {
  std::vector<Point> vertices;
  std::vector<std::pair<int, int>> detected;
};
PlainVertices plain_vertices(const std::vector<Segment>& segments) {
  PlainVertices plain;
  std::map<std::pair<double, double>, int> id;
  auto vertex = [&](const Point& p) {
    auto [it, inserted] = id.try_emplace({p.x, p.y}, static_cast<int>(plain.vertices.size()));
    if (inserted) plain.vertices.push_back(p);
    return it->second;
  };
  std::set<std::pair<int, int>> seen;
  for (const Segment& s : segments) {
    const int u = vertex(s.a), v = vertex(s.b);
    if (u == v || !seen.insert({std::min(u, v), std::max(u, v)}).second) continue;
    plain.detected.push_back({u, v});
  }
  return plain;
}

class SegmentGraphReuse : public ::testing::TestWithParam<unsigned> {};

// Segments on a coarse grid share and repeat endpoints and edges often; the graph numbers
// vertices in order of first appearance, keeps the first of repeated segments, and a graph
// rebuilt into a reused object equals a fresh one.
TEST_P(SegmentGraphReuse, MatchesPlainNumberingAndReusedBuildsMatchFreshOnes) {
  std::mt19937 rng(GetParam() * 7u + 3u);
  std::uniform_int_distribution<int> grid(0, 6), count(0, 40);
  SegmentGraph reused;
  for (int frame = 0; frame < 3; ++frame) {
    std::vector<Segment> segments(count(rng));
    for (Segment& s : segments) {
      s = {Point(10.0 * grid(rng), 10.0 * grid(rng)), Point(10.0 * grid(rng), 10.0 * grid(rng))};
    }
    const PlainVertices plain = plain_vertices(segments);
    const SegmentGraph fresh = build_segment_graph(segments);
    build_segment_graph(segments, &reused);
    ASSERT_EQ(fresh.vertices, plain.vertices);
    ASSERT_EQ(fresh.detected_edges.size(), plain.detected.size());
    for (size_t k = 0; k < plain.detected.size(); ++k) {
      const GraphEdge& e = fresh.edges[fresh.detected_edges[k]];
      EXPECT_EQ(e.u, plain.detected[k].first);
      EXPECT_EQ(e.v, plain.detected[k].second);
      EXPECT_TRUE(e.detected);
      EXPECT_EQ(e.weight, 0.0);
    }
    // No edge twice, and generated edges are exactly the non-detected ones.
    std::set<std::pair<int, int>> pairs;
    for (const GraphEdge& e : fresh.edges) {
      EXPECT_TRUE(pairs.insert({std::min(e.u, e.v), std::max(e.u, e.v)}).second);
      EXPECT_EQ(e.detected, e.weight == 0.0);
    }
    ASSERT_EQ(reused.vertices, fresh.vertices);
    ASSERT_EQ(reused.edges.size(), fresh.edges.size());
    for (size_t i = 0; i < fresh.edges.size(); ++i) {
      EXPECT_EQ(reused.edges[i].u, fresh.edges[i].u);
      EXPECT_EQ(reused.edges[i].v, fresh.edges[i].v);
      EXPECT_EQ(reused.edges[i].weight, fresh.edges[i].weight);
    }
    EXPECT_EQ(reused.detected_edges, fresh.detected_edges);
    EXPECT_EQ(reused.adjacency_begin, fresh.adjacency_begin);
  }
}

INSTANTIATE_TEST_SUITE_P(Seeds, SegmentGraphReuse, ::testing::Range(0u, 100u));

// The generated edges written the straightforward way: the vertices handed to CGAL's range
// constructor in a shuffled order, every finite edge collected in an ordered set, the detected
// ones removed.
std::vector<std::pair<int, int>> plain_generated_edges(const SegmentGraph& graph,
                                                       std::mt19937& rng) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
  using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, CGAL::Triangulation_data_structure_2<Vb>>;
  std::vector<std::pair<Kernel::Point_2, int>> sites;
  for (int v = 0; v < graph.num_vertices(); ++v) {
    sites.emplace_back(Kernel::Point_2(graph.vertices[v].x, graph.vertices[v].y), v);
  }
  std::shuffle(sites.begin(), sites.end(), rng);
  const Delaunay triangulation(sites.begin(), sites.end());
  std::set<std::pair<int, int>> edges;
  for (auto e = triangulation.finite_edges_begin(); e != triangulation.finite_edges_end(); ++e) {
    const int u = e->first->vertex(Delaunay::cw(e->second))->info();
    const int v = e->first->vertex(Delaunay::ccw(e->second))->info();
    edges.emplace(std::min(u, v), std::max(u, v));
  }
  for (int k : graph.detected_edges) {
    const GraphEdge& e = graph.edges[k];
    edges.erase({std::min(e.u, e.v), std::max(e.u, e.v)});
  }
  return {edges.begin(), edges.end()};
}

class SegmentGraphGenerated : public ::testing::TestWithParam<unsigned> {};

// The generated edges are exactly the Delaunay edges that are not detected, in (lower, higher)
// vertex order, after the detected ones, whatever order the points are triangulated in: checked
// on general segments and on grid segments, whose points are often cocircular (where the
// Delaunay triangulation is not unique without CGAL's symbolic perturbation) or collinear.
TEST_P(SegmentGraphGenerated, EqualsPlainTriangulationInAnyInsertionOrder) {
  std::mt19937 rng(GetParam() * 13u + 5u);
  std::uniform_int_distribution<int> grid(0, 5), count(1, 40);
  std::vector<Segment> segments;
  if (GetParam() % 2 == 0) {
    segments = random_segments(rng, count(rng));
  } else {
    segments.resize(count(rng));
    for (Segment& s : segments) {
      s = {Point(10.0 * grid(rng), 10.0 * grid(rng)), Point(10.0 * grid(rng), 10.0 * grid(rng))};
    }
  }
  const SegmentGraph graph = build_segment_graph(segments);
  const int num_detected = static_cast<int>(graph.detected_edges.size());
  for (int k = 0; k < num_detected; ++k) EXPECT_EQ(graph.detected_edges[k], k);
  std::vector<std::pair<int, int>> generated;
  for (int i = num_detected; i < graph.num_edges(); ++i) {
    const GraphEdge& e = graph.edges[i];
    EXPECT_FALSE(e.detected);
    EXPECT_EQ(e.length, cv::norm(graph.vertices[e.u] - graph.vertices[e.v]));
    EXPECT_EQ(e.weight, e.length);
    generated.emplace_back(e.u, e.v);
  }
  for (int trial = 0; trial < 3; ++trial) {
    EXPECT_EQ(generated, plain_generated_edges(graph, rng)) << "trial " << trial;
  }
}

INSTANTIATE_TEST_SUITE_P(Seeds, SegmentGraphGenerated, ::testing::Range(0u, 200u));

}  // namespace
}  // namespace scbt
