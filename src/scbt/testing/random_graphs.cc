#include "scbt/testing/random_graphs.h"

#include <algorithm>
#include <cmath>

namespace scbt {
namespace {

constexpr double kPi = 3.14159265358979323846;

double cross(const Point& o, const Point& a, const Point& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

}  // namespace

bool properly_cross(const Segment& s, const Segment& t) {
  const double d1 = cross(s.a, s.b, t.a), d2 = cross(s.a, s.b, t.b);
  const double d3 = cross(t.a, t.b, s.a), d4 = cross(t.a, t.b, s.b);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

std::vector<Segment> random_segments(std::mt19937& rng, int count, bool share_endpoints) {
  std::uniform_real_distribution<double> pos(0.0, 300.0), len(5.0, 50.0), angle(-kPi, kPi);
  std::uniform_int_distribution<int> coin(0, 3);
  std::vector<Segment> segments;
  for (int attempt = 0; static_cast<int>(segments.size()) < count && attempt < 50 * count;
       ++attempt) {
    Point a(pos(rng), pos(rng));
    if (share_endpoints && !segments.empty() && coin(rng) == 0) {
      a = segments[std::uniform_int_distribution<size_t>(0, segments.size() - 1)(rng)].b;
    }
    const double t = angle(rng);
    const Segment s{a, a + Point(std::cos(t), std::sin(t)) * len(rng)};
    if (std::none_of(segments.begin(), segments.end(),
                     [&](const Segment& other) { return properly_cross(s, other); })) {
      segments.push_back(s);
    }
  }
  return segments;
}

SegmentGraph random_multigraph(std::mt19937& rng, int n, int m,
                               const std::function<double(std::mt19937&)>& gap_weight) {
  SegmentGraph graph;
  std::uniform_real_distribution<double> pos(0.0, 100.0);
  std::uniform_int_distribution<int> vertex(0, n - 1), coin(0, 3);
  for (int i = 0; i < n; ++i) graph.vertices.emplace_back(pos(rng), pos(rng));
  for (int i = 0; i < m; ++i) {
    GraphEdge e;
    e.u = vertex(rng);
    do {
      e.v = vertex(rng);
    } while (e.v == e.u);
    e.detected = coin(rng) == 0;
    e.weight = e.detected ? 0.0 : gap_weight(rng);
    e.length = e.weight;
    if (e.detected) graph.detected_edges.push_back(i);
    graph.edges.push_back(e);
  }
  build_adjacency(&graph);
  return graph;
}

}  // namespace scbt
