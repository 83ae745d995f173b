#include "scbt/grouping/bdsp.h"

#include <algorithm>

#include "scbt/grouping/shortest_paths.h"

namespace scbt {
namespace {

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

Polygon candidate_polygon(const SegmentGraph& graph, const CycleCandidate& candidate) {
  Polygon polygon;
  polygon.reserve(candidate.vertices.size());
  for (int v : candidate.vertices) polygon.push_back(graph.vertices[v]);
  return polygon;
}

std::vector<CycleCandidate> search_cycle_candidates(const SegmentGraph& graph,
                                                    const BdspOptions& options) {
  std::vector<CycleCandidate> candidates;
  const int n = graph.num_vertices();
  const int stride = std::max(1, options.seed_stride);
  ShortestPaths from_first, from_second;
  // Stamps avoid clearing per-vertex marks for every candidate.
  std::vector<int> on_second_path(n, -1), meeting_seen(n, -1);
  std::vector<int> first_path;
  int stamp = 0;

  const int num_detected = static_cast<int>(graph.detected_edges.size());
  for (int i = 0; i < num_detected; i += stride) {
    const int seed = graph.detected_edges[i];
    const int s1 = graph.edges[seed].u;
    const int s2 = graph.edges[seed].v;
    from_first.run(graph, s1, seed);
    from_second.run(graph, s2, seed);
    for (int j = 0; j < num_detected; ++j) {
      if (j == i) continue;
      const int third = graph.edges[graph.detected_edges[j]].u;
      if (!from_first.reached(third) || !from_second.reached(third)) continue;

      ++stamp;
      for (int v = third; v != -1; v = from_second.parent_vertex(v)) on_second_path[v] = stamp;
      // Walk the first path back from the third vertex; the meeting vertex is the marked vertex
      // nearest to s1 along it.
      first_path.clear();
      for (int v = third; v != -1; v = from_first.parent_vertex(v)) first_path.push_back(v);
      std::reverse(first_path.begin(), first_path.end());  // s1 ... third
      size_t meet = 0;
      while (on_second_path[first_path[meet]] != stamp) ++meet;
      const int meeting = first_path[meet];
      if (meeting_seen[meeting] == i) continue;  // same cycle as an earlier candidate of this seed
      meeting_seen[meeting] = i;

      CycleCandidate candidate;
      candidate.seed_edge = seed;
      candidate.vertices.assign(first_path.begin(), first_path.begin() + meet + 1);
      // Then back from the meeting vertex to s2 along the second path.
      for (int v = meeting; v != s2; v = from_second.parent_vertex(v)) {
        candidate.vertices.push_back(from_second.parent_vertex(v));
      }
      if (candidate.vertices.size() < 3) continue;
      // The blocked seed edge weighs 0, so the gap is what the two paths add up to.
      candidate.gap_length = from_first.distance(meeting) + from_second.distance(meeting);
      candidate.area = cycle_area(graph, candidate.vertices);
      candidates.push_back(std::move(candidate));
    }
  }
  return candidates;
}

}  // namespace scbt
