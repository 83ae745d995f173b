#include "scbt/cycles/bdsp.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

namespace scbt {

void BdspOptions::check() const {
  if (seed_stride < 1) {
    throw std::invalid_argument("bdsp seed_stride must be at least 1, got " +
                                std::to_string(seed_stride));
  }
}

Polygon candidate_polygon(const SegmentGraph& graph, const CycleCandidate& candidate) {
  Polygon polygon;
  polygon.reserve(candidate.vertices.size());
  for (int v : candidate.vertices) polygon.push_back(graph.vertices[v]);
  return polygon;
}

namespace {

double cross(const Point& p, const Point& q) { return p.x * q.y - q.x * p.y; }

// Frontier keys: (distance, unit id) in one unsigned 128-bit integer, so that the settle order
// (distance first, then id: whatever else the frontier holds, so a bounded search settles what
// it keeps as the unbounded one does) is a single comparison. Distances are non-negative, and
// the bits of non-negative doubles order as the doubles do.
using FrontierKey = unsigned __int128;

FrontierKey frontier_key(double distance, int unit) {
  uint64_t bits;
  std::memcpy(&bits, &distance, sizeof bits);
  return (static_cast<FrontierKey>(bits) << 32) | static_cast<uint32_t>(unit);
}

int key_unit(FrontierKey key) { return static_cast<int>(static_cast<uint32_t>(key)); }

}  // namespace

// Settles units in (distance, unit id) order and relaxes each unit's arcs (then its extra arcs
// into the open seed's units) with a strict comparison: a shortest-path tree of the units, so of
// the graph vertices (entry_vertex), equal to the vertex search's but where path lengths tie.
int CycleSearch::shortest_paths(int tree, int source, int num_thirds, double limit, int stamp) {
  double* distance = distance_[tree].data();
  int* parent = parent_arc_[tree].data();
  int* order = order_[tree].data();
  int* settled_by = settled_[tree].data();
  std::fill(distance, distance + num_units_ + 1, std::numeric_limits<double>::infinity());

  const Arc* arcs = arcs_.data();
  const int* begin = unit_begin_.data();
  const int* end_of = unit_end_.data();
  const int* extra_head = extra_head_.data();
  const int* extra_next = extra_next_.data();
  const char* is_third = tree == 0 ? unit_third_.data() : wanted_.data();
  int* position = frontier_position_.data();
  FrontierKey* frontier = frontier_.data();
  distance[source] = 0.0;
  parent[source] = -1;
  frontier[0] = frontier_key(0.0, source);
  position[source] = 0;
  int settled = 0, thirds_left = num_thirds;
  int size = 1;
  // A unit not in the frontier goes in slot `size` (only kept if it improved). Arcs are sorted
  // by weight so that a bounded search stops at the first one past `limit`; the variants tried
  // and measured slower are in docs/dev/performance-notes.md.
  const auto relax = [&](double d, int k) {
    const double candidate = d + arcs[k].weight;
    const int w = arcs[k].unit;
    const double old = distance[w];
    const bool better = candidate < old;
    distance[w] = better ? candidate : old;
    parent[w] = better ? k : parent[w];
    const int at = position[w];
    const int slot = at < 0 ? size : at;
    const FrontierKey key = frontier_key(better ? candidate : old, w);
    frontier[slot] = better ? key : frontier[slot];
    position[w] = better ? slot : at;
    size += better & (at < 0);
  };
  while (size > 0) {
    // The frontier is small (about a dozen units on these graphs): an unordered array scanned
    // for its least (distance, id) key beats a heap's unpredictable branches.
    int best = 0;
    FrontierKey least = frontier[0];
    for (int k = 1; k < size; ++k) {
      const bool less = frontier[k] < least;
      least = less ? frontier[k] : least;
      best = less ? k : best;
    }
    const int u = key_unit(least);
    const FrontierKey moved = frontier[--size];
    frontier[best] = moved;
    position[key_unit(moved)] = best;
    position[u] = -1;
    order[settled++] = u;
    settled_by[u] = stamp;
    thirds_left -= is_third[u];
    if (thirds_left == 0) break;  // the rest is never used
    const double d = distance[u];
    // Arcs are sorted by weight (blocked ones aside, which weigh infinity in place): the arcs
    // past `limit` are the last ones. With no limit (infinity) none is.
    int end = end_of[u];
    while (end > begin[u] && d + arcs[end - 1].weight > limit) --end;
    for (int k = begin[u]; k < end; ++k) relax(d, k);
    for (int k = extra_head[u]; k >= 0; k = extra_next[k]) {
      if (d + arcs[k].weight <= limit) relax(d, k);
    }
  }
  for (int k = 0; k < size; ++k) position[key_unit(frontier[k])] = -1;
  return settled;
}

void CycleSearch::open_seed(const SegmentGraph& graph, int seed, int s1, int s2) {
  std::vector<int>& unit_of = units_.unit_of;
  std::vector<int>& partner = units_.partner;
  const int a = unit_of[s1];
  // A segment unit splits (s2 takes the spare id); otherwise s1 and s2 are units of their own.
  if (partner[s1] == s2) {
    unit_of[s2] = num_units_;
    partner[s1] = partner[s2] = -1;
  }
  const int b = unit_of[s2];
  blocked_.clear();
  for (const int part : {a, b}) {
    if (part == num_units_) continue;
    for (int k = units_.arc_begin[part]; k < units_.arc_begin[part + 1]; ++k) {
      const int r = units_.reverse[k];
      blocked_.push_back({r, arcs_[r].weight});
      arcs_[r].weight = std::numeric_limits<double>::infinity();
    }
  }
  arcs_.resize(units_.arcs.size());
  for (const int s : {s1, s2}) {
    const int part = unit_of[s];
    const int first = static_cast<int>(arcs_.size());
    for (int k = graph.adjacency_begin[s]; k < graph.adjacency_begin[s + 1]; ++k) {
      const SegmentGraph::Incidence& in = graph.adjacency[k];
      if (in.edge == seed) continue;
      // By weight (a handful of arcs), as every unit's.
      const Arc arc{unit_of[in.vertex], s, in.vertex, graph.edges[in.edge].weight};
      arcs_.push_back(arc);
      int at = static_cast<int>(arcs_.size()) - 1;
      for (; at > first && arcs_[at - 1].weight > arc.weight; --at) arcs_[at] = arcs_[at - 1];
      arcs_[at] = arc;
    }
    unit_begin_[part] = first;
    unit_end_[part] = static_cast<int>(arcs_.size());
  }
  // The same edges the other way, from the neighbouring units.
  const int own_end = static_cast<int>(arcs_.size());
  extra_next_.resize(arcs_.size() + (own_end - units_.arcs.size()));
  for (int k = static_cast<int>(units_.arcs.size()); k < own_end; ++k) {
    const Arc arc = arcs_[k];
    if (arc.unit == a || arc.unit == b) continue;
    extra_next_[arcs_.size()] = extra_head_[arc.unit];
    extra_head_[arc.unit] = static_cast<int>(arcs_.size());
    arcs_.push_back({unit_of[arc.from], arc.to, arc.from, arc.weight});
  }
}

void CycleSearch::close_seed(int s1, int s2) {
  std::vector<int>& unit_of = units_.unit_of;
  const int own_begin = static_cast<int>(units_.arcs.size());
  for (int k = own_begin; k < unit_end_[unit_of[s2]]; ++k) extra_head_[arcs_[k].unit] = -1;
  for (const auto& [k, weight] : blocked_) arcs_[k].weight = weight;
  for (const int s : {s1, s2}) {
    const int part = unit_of[s];
    if (part < num_units_) {
      unit_begin_[part] = units_.arc_begin[part];
      unit_end_[part] = units_.arc_begin[part + 1];
    }
  }
  if (unit_of[s2] == num_units_) {
    unit_of[s2] = unit_of[s1];
    units_.partner[s1] = s2;
    units_.partner[s2] = s1;
  }
}

// The graph-vertex trees: each unit's entry vertex (where its parent arc arrives) hangs from the
// vertex the arc leaves, the other end of a segment unit from the entry (by the zero-weight
// segment). Parents settle before children, so one pass in settle order fills each tree.
inline int CycleSearch::entry_vertex(int tree, int k, int root, int* parent) const {
  if (k == 0) {
    parent[root] = -1;
    return root;
  }
  const Arc& arc = arcs_[parent_arc_[tree][order_[tree][k]]];
  parent[arc.to] = arc.from;
  return arc.to;
}

// Second tree: parents, shoelace sums and the pre-order interval [enter, enter + size) of each
// vertex, from subtree sizes (a unit's vertices after its parent's, its other end after its
// entry). Vertices outside the tree get size 0.
void CycleSearch::second_tree_pass(const Point* points, int s2, int settled, int* parent) {
  const int* order = order_[1].data();
  const int* parent_arc = parent_arc_[1].data();
  const int* partner = units_.partner.data();
  int* size = size_.data();
  int* enter = enter_.data();
  int* next = next_.data();
  double* sum = shoelace_[1].data();
  std::fill(size_.begin(), size_.end(), 0);
  for (int k = settled - 1; k >= 0; --k) {
    const Arc* arc = k > 0 ? &arcs_[parent_arc[order[k]]] : nullptr;
    const int e = k > 0 ? arc->to : s2;
    const int o = partner[e];
    if (o >= 0) size[e] += ++size[o];
    ++size[e];
    if (k > 0) size[arc->from] += size[e];
  }
  for (int k = 0; k < settled; ++k) {
    const int e = entry_vertex(1, k, s2, parent);
    const int p = parent[e];
    if (p < 0) {
      sum[e] = 0.0;
      enter[e] = 0;
    } else {
      sum[e] = sum[p] + cross(points[p], points[e]);
      enter[e] = next[p];
      next[p] += size[e];
    }
    next[e] = enter[e] + 1;
    const int o = partner[e];
    if (o >= 0) {
      parent[o] = e;
      sum[o] = sum[e] + cross(points[e], points[o]);
      enter[o] = next[e];
      next[e] += size[o];
      next[o] = enter[o] + 1;
    }
  }
}

// First tree (after the second): parents, shoelace sums, bound[v] (the largest d1 - d2 on the
// path s1 ... v) and fork[v] (see the walk in run).
void CycleSearch::first_tree_pass(const Point* points, int s1, int settled, int slot, int* parent,
                                  const int* parent2) {
  const int* partner = units_.partner.data();
  const double* d1 = distance_[0].data();
  const double* d2 = distance_[1].data();
  const int* order = order_[0].data();
  const int* settled_by2 = settled_[1].data();
  double* sum = shoelace_[0].data();
  double* bound = bound_.data();
  int* fork = fork_.data();
  for (int k = 0; k < settled; ++k) {
    const int u = order[k];
    const int e = entry_vertex(0, k, s1, parent);
    const int p = parent[e];
    const bool in_second = settled_by2[u] == slot;
    const double difference = d1[u] - d2[u];
    if (p < 0) {
      sum[e] = 0.0;
      bound[e] = difference;
      fork[e] = e;
    } else {
      sum[e] = sum[p] + cross(points[p], points[e]);
      bound[e] = std::max(bound[p], difference);
      fork[e] = in_second && parent2[e] == p ? fork[p] : e;
    }
    const int o = partner[e];
    if (o >= 0) {
      parent[o] = e;
      sum[o] = sum[e] + cross(points[e], points[o]);
      bound[o] = bound[e];
      fork[o] = in_second && parent2[o] == e ? fork[e] : o;
    }
  }
}

void CycleSearch::run(const SegmentGraph& graph, const BdspOptions& options,
                      CandidatePruner* pruner) {
  const int n = graph.num_vertices();
  options.check();
  if (pruner != nullptr) pruner->start();
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  seed_limits_.clear();
  const int stride = options.seed_stride;
  const int num_detected = static_cast<int>(graph.detected_edges.size());
  num_vertices_ = n;
  candidates_.clear();
  found_.clear();
  seed_source_.clear();

  // The graph once, in the layout the searches read: contracted, without the arcs no search
  // needs. The margin of a useless arc is far above the rounding error of any path sum.
  double total = 0.0;
  for (const GraphEdge& e : graph.edges) total += e.weight;
  tolerance_ = 1e-9 * (1.0 + total);
  build_segment_units(graph, &units_);
  num_units_ = units_.num_units;
  // Each seed opens the units of its two ends (open_seed).
  opened_by_.assign(num_units_, -1);
  for (int i = 0; i < num_detected; i += stride) {
    const int seed = graph.detected_edges[i];
    for (const int end : {graph.edges[seed].u, graph.edges[seed].v}) {
      int& opener = opened_by_[units_.unit_of[end]];
      opener = opener == -1 || opener == seed ? seed : -2;
    }
  }
  drop_dominated_arcs(opened_by_, tolerance_, &units_);
  const int num_ids = num_units_ + 1;  // and the spare id of s2's unit during a seed
  arcs_ = units_.arcs;
  unit_begin_.assign(units_.arc_begin.begin(), units_.arc_begin.end() - 1);
  unit_begin_.push_back(0);
  unit_end_.assign(units_.arc_begin.begin() + 1, units_.arc_begin.end());
  unit_end_.push_back(0);
  extra_head_.assign(num_ids, -1);
  unit_third_.assign(num_ids, 0);
  wanted_.assign(num_ids, 0);
  num_third_units_ = 0;
  for (int e : graph.detected_edges) {
    const int unit = units_.unit_of[graph.edges[e].u];
    if (!unit_third_[unit]) {
      unit_third_[unit] = 1;
      ++num_third_units_;
    }
  }
  for (int tree = 0; tree < 2; ++tree) {
    distance_[tree].resize(num_ids);
    parent_arc_[tree].resize(num_ids);
    order_[tree].resize(num_ids);
    settled_[tree].assign(num_ids, -1);
    shoelace_[tree].resize(n);
  }
  bound_.resize(n);
  points_.resize(n);
  fork_.resize(n);
  enter_.resize(n);
  next_.resize(n);
  size_.resize(n);
  frontier_position_.assign(num_ids, -1);
  frontier_.resize(num_ids + 1);
  meeting_seen_.assign(n, -1);
  const int num_seeds = num_detected > 0 ? (num_detected + stride - 1) / stride : 0;
  parents_.resize(static_cast<size_t>(2) * num_seeds * n);

  const std::vector<int>& unit_of = units_.unit_of;
  for (int i = 0, slot = 0; i < num_detected; i += stride, ++slot) {
    const int seed = graph.detected_edges[i];
    const int s1 = graph.edges[seed].u;
    const int s2 = graph.edges[seed].v;
    seed_source_.push_back(s1);
    seed_source_.push_back(s2);
    int* parent1 = parents_.data() + static_cast<size_t>(2 * slot) * n;
    int* parent2 = parent1 + n;
    open_seed(graph, seed, s1, s2);
    const double limit = pruner != nullptr ? pruner->gap_limit() : kInfinity;
    seed_limits_.push_back(limit);
    const int settled1 = shortest_paths(0, unit_of[s1], num_third_units_, limit, slot);
    // Only the third vertices the first tree settled can close a cycle: the second search
    // waits for those alone.
    int wanted = 0;
    for (int k = 0; k < settled1; ++k) {
      const int u = order_[0][k];
      wanted_[u] = unit_third_[u];
      wanted += unit_third_[u];
    }
    const int settled2 = shortest_paths(1, unit_of[s2], wanted, limit, slot);
    for (int k = 0; k < settled1; ++k) wanted_[order_[0][k]] = 0;
    // Coordinates relative to s1 (smaller shoelace terms).
    const Point origin = graph.vertices[s1];
    for (int v = 0; v < n; ++v) points_[v] = graph.vertices[v] - origin;
    second_tree_pass(points_.data(), s2, settled2, parent2);
    first_tree_pass(points_.data(), s1, settled1, slot, parent1, parent2);

    const double* d1 = distance_[0].data();
    const double* d2 = distance_[1].data();
    const int* settled_by1 = settled_[0].data();
    const int* settled_by2 = settled_[1].data();
    const double* sum1 = shoelace_[0].data();
    const double* sum2 = shoelace_[1].data();
    const int* enter = enter_.data();
    const int* size = size_.data();
    const double* bound = bound_.data();
    const int* fork = fork_.data();
    for (int j = 0; j < num_detected; ++j) {
      if (j == i) continue;
      const int third = graph.edges[graph.detected_edges[j]].u;
      const int third_unit = unit_of[third];
      if (settled_by1[third_unit] != slot || settled_by2[third_unit] != slot) continue;

      // The paths s1 -> third and third -> s2 meet at the vertex of the first path nearest s1
      // that also lies on the second, i.e. is an ancestor-or-self of `third` in the second tree.
      // A vertex v on both paths has d1(v) - d2(v) = d1(third) - d2(third) (both continue by a
      // shortest path v ... third; up to rounding, far below `tolerance_`), while elsewhere on
      // the first path the difference is smaller; so the walk up the first path stops where
      // nothing above can be on the second (bound = the largest difference from s1 down).
      const double limit = d1[third_unit] - d2[third_unit] - tolerance_;
      // From `third` up to fork[third] both trees follow the same parents, so all of it is on
      // both paths; only above the fork can the paths share a vertex again (where they tie).
      // A vertex outside the second tree has size 0: never an ancestor.
      const unsigned third_enter = static_cast<unsigned>(enter[third]);
      int meeting = fork[third];
      for (int v = parent1[meeting]; v != -1 && bound[v] >= limit; v = parent1[v]) {
        if (third_enter - static_cast<unsigned>(enter[v]) < static_cast<unsigned>(size[v])) {
          meeting = v;
        }
      }
      if (meeting_seen_[meeting] == i) continue;  // same cycle as an earlier candidate
      meeting_seen_[meeting] = i;
      // Fewer than three vertices: s1 and s2 joined directly (by the tree of the other).
      if ((meeting == s1 && parent2[s1] == s2) || (meeting == s2 && parent1[s2] == s1)) continue;

      CandidateSummary c;
      c.seed_edge = seed;
      // The blocked seed edge weighs 0, so the gap is what the two paths add up to.
      const int meeting_unit = unit_of[meeting];
      c.gap_length = d1[meeting_unit] + d2[meeting_unit];
      c.area = 0.5 * std::abs(sum1[meeting] - sum2[meeting]);
      if (pruner != nullptr && !pruner->keep(c)) continue;
      candidates_.push_back(c);
      found_.push_back({slot, meeting});
    }
    close_seed(s1, s2);
  }
}

void CycleSearch::vertices(int k, std::vector<int>* out) const {
  const Found& f = found_.at(k);
  const int n = num_vertices_;
  const int* parent1 = parents_.data() + static_cast<size_t>(2 * f.seed_slot) * n;
  const int* parent2 = parent1 + n;
  const int s2 = seed_source_[2 * f.seed_slot + 1];
  out->clear();
  for (int v = f.meeting; v != -1; v = parent1[v]) out->push_back(v);
  std::reverse(out->begin(), out->end());
  for (int v = f.meeting; v != s2; v = parent2[v]) out->push_back(parent2[v]);
}

CycleCandidate CycleSearch::candidate(int k) const {
  CycleCandidate c;
  const CandidateSummary& s = candidates_.at(k);
  c.gap_length = s.gap_length;
  c.area = s.area;
  c.seed_edge = s.seed_edge;
  vertices(k, &c.vertices);
  return c;
}

std::vector<CycleCandidate> search_cycle_candidates(const SegmentGraph& graph,
                                                    const BdspOptions& options) {
  thread_local CycleSearch search;
  search.run(graph, options);
  std::vector<CycleCandidate> candidates(search.size());
  for (int k = 0; k < search.size(); ++k) candidates[k] = search.candidate(k);
  return candidates;
}

}  // namespace scbt
