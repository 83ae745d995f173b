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

namespace {

// Per-thread buffers reused across calls, so that a tracker allocates nothing here in steady
// state but the candidates it returns.
struct Workspace {
  ShortestPaths from_first, from_second;
  std::vector<int> meeting_seen;
  // Pre-order interval of every vertex in the second search's tree: u is an ancestor-or-self of v
  // exactly when enter[u] <= enter[v] < leave[u].
  std::vector<int> enter, leave;
  std::vector<int> child_begin, children, stack;
  std::vector<int> path;
};

// Numbers the tree of `paths` (rooted at `root`) in pre-order (iterative depth-first search over
// child lists built from the parent links).
void number_tree(const ShortestPaths& paths, int root, int n, Workspace* ws) {
  std::vector<int>& begin = ws->child_begin;
  std::vector<int>& cursor = ws->path;
  begin.assign(n + 1, 0);
  for (int v = 0; v < n; ++v) {
    if (v != root && paths.reached(v)) ++begin[paths.parent_vertex(v) + 1];
  }
  for (int v = 0; v < n; ++v) begin[v + 1] += begin[v];
  ws->children.resize(begin[n]);
  cursor.assign(begin.begin(), begin.end() - 1);
  for (int v = 0; v < n; ++v) {
    if (v != root && paths.reached(v)) ws->children[cursor[paths.parent_vertex(v)]++] = v;
  }
  cursor.assign(begin.begin(), begin.end() - 1);  // next child to visit, per vertex
  ws->enter.assign(n, -1);
  ws->leave.assign(n, -1);
  ws->stack.clear();
  int clock = 0;
  ws->enter[root] = clock++;
  ws->stack.push_back(root);
  while (!ws->stack.empty()) {
    const int u = ws->stack.back();
    if (cursor[u] < begin[u + 1]) {
      const int c = ws->children[cursor[u]++];
      ws->enter[c] = clock++;
      ws->stack.push_back(c);
    } else {
      ws->leave[u] = clock;
      ws->stack.pop_back();
    }
  }
}

}  // namespace

std::vector<CycleCandidate> search_cycle_candidates(const SegmentGraph& graph,
                                                    const BdspOptions& options) {
  std::vector<CycleCandidate> candidates;
  const int n = graph.num_vertices();
  const int stride = std::max(1, options.seed_stride);
  thread_local Workspace ws;
  ShortestPaths& from_first = ws.from_first;
  ShortestPaths& from_second = ws.from_second;
  ws.meeting_seen.assign(n, -1);

  const int num_detected = static_cast<int>(graph.detected_edges.size());
  for (int i = 0; i < num_detected; i += stride) {
    const int seed = graph.detected_edges[i];
    const int s1 = graph.edges[seed].u;
    const int s2 = graph.edges[seed].v;
    from_first.run(graph, s1, seed);
    from_second.run(graph, s2, seed);
    number_tree(from_second, s2, n, &ws);
    for (int j = 0; j < num_detected; ++j) {
      if (j == i) continue;
      const int third = graph.edges[graph.detected_edges[j]].u;
      if (!from_first.reached(third) || !from_second.reached(third)) continue;

      // The paths s1 -> third and third -> s2 meet at the vertex of the first path nearest s1
      // that also lies on the second, i.e. is an ancestor-or-self of `third` in the second tree.
      const int third_enter = ws.enter[third];
      int meeting = third;
      for (int v = from_first.parent_vertex(third); v != -1; v = from_first.parent_vertex(v)) {
        if (ws.enter[v] >= 0 && ws.enter[v] <= third_enter && third_enter < ws.leave[v]) {
          meeting = v;
        }
      }
      if (ws.meeting_seen[meeting] == i) continue;  // same cycle as an earlier candidate
      ws.meeting_seen[meeting] = i;

      CycleCandidate candidate;
      candidate.seed_edge = seed;
      // s1 ... meeting along the first path, then back to s2 along the second.
      ws.stack.clear();
      for (int v = meeting; v != -1; v = from_first.parent_vertex(v)) ws.stack.push_back(v);
      size_t size = ws.stack.size();
      for (int v = meeting; v != s2; v = from_second.parent_vertex(v)) ++size;
      if (size < 3) continue;
      candidate.vertices.reserve(size);
      candidate.vertices.assign(ws.stack.rbegin(), ws.stack.rend());
      for (int v = meeting; v != s2; v = from_second.parent_vertex(v)) {
        candidate.vertices.push_back(from_second.parent_vertex(v));
      }
      // The blocked seed edge weighs 0, so the gap is what the two paths add up to.
      candidate.gap_length = from_first.distance(meeting) + from_second.distance(meeting);
      candidate.area = cycle_area(graph, candidate.vertices);
      candidates.push_back(std::move(candidate));
    }
  }
  return candidates;
}

}  // namespace scbt
