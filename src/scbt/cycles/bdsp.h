// Stage 5: Bidirectional Shortest Path cycle candidates (paper §III-D, Fig. 4e, Algorithm 1).
#pragma once

#include <utility>
#include <vector>

#include "scbt/cycles/segment_units.h"
#include "scbt/geometry/polygon.h"
#include "scbt/graph/segment_graph.h"

namespace scbt {

struct CycleCandidate {
  std::vector<int> vertices;  // graph vertex ids in cycle order; the cycle closes back to front
  double gap_length = 0.0;    // |B_G|: total length of generated edges on the cycle
  double area = 0.0;          // enclosed area (shoelace)
  int seed_edge = -1;         // the detected edge e_i the cycle was grown from
};

struct BdspOptions {
  // Seeds are every `seed_stride`-th detected segment (the paper samples every other one: 2).
  int seed_stride = 2;

  // Throws std::invalid_argument naming a bad value (seed_stride < 1).
  void check() const;
};

// What the boundary choice needs of a candidate; its vertices are listed on demand
// (CycleSearch::vertices).
struct CandidateSummary {
  double gap_length = 0.0;  // |B_G|, as in CycleCandidate
  double area = 0.0;        // enclosed area, as in CycleCandidate (to ~1e-9 relative)
  int seed_edge = -1;       // the detected edge e_i the cycle was grown from
};

// Lets CycleSearch keep only the candidates a caller can use and bound each seed's Dijkstras by
// the longest gap such a candidate can have (reference/candidate_gate.h prunes for the choice).
class CandidatePruner {
 public:
  virtual ~CandidatePruner() = default;
  // Called once at the start of a run.
  virtual void start() = 0;
  // The gap bound for the next seed's searches (infinity: unbounded).
  virtual double gap_limit() const = 0;
  // Whether to keep a found candidate; called in list order.
  virtual bool keep(const CandidateSummary& candidate) = 0;
};

// The BDSP search of search_cycle_candidates without materialising candidates: each candidate
// is a summary plus the vertex where its two shortest paths meet; each seed's two trees are kept
// so that any candidate's cycle can be listed afterwards. Same candidates, in the same order, as
// the straightforward search (reference/bdsp_generic.h) up to shortest-path ties. It is fast
// because Dijkstra runs over contracted segments (segment_units.h) with a small unordered
// frontier, areas come from root-to-vertex shoelace sums, and nothing is allocated once warm
// (docs/performance.md). Not thread-safe; use one object per thread.
//
// With a pruner, seed i's Dijkstras settle only units within pruner->gap_limit() of their root
// (arcs u -> w with d(u) + weight > limit are not relaxed), so distances and parents within the
// limit are the unbounded search's bit for bit; candidates the pruner rejects are dropped.
class CycleSearch {
 public:
  // Throws std::invalid_argument for bad options (BdspOptions::check, the pruner's start()).
  // pruner == nullptr: every candidate, unbounded searches (as search_cycle_candidates).
  void run(const SegmentGraph& graph, const BdspOptions& options = {},
           CandidatePruner* pruner = nullptr);

  // The candidates of search_cycle_candidates, in the same order, with bit-identical gaps and
  // areas equal to ~1e-9 relative (summed in another order). Where path lengths tie, other
  // shortest paths than a vertex-by-vertex Dijkstra's (see above).
  const std::vector<CandidateSummary>& candidates() const { return candidates_; }
  int size() const { return static_cast<int>(candidates_.size()); }
  // Candidate k's cycle (graph vertex ids; the cycle closes back to front), into *out.
  void vertices(int k, std::vector<int>* out) const;
  // Candidate k in full (vertices included), as search_cycle_candidates gives it.
  CycleCandidate candidate(int k) const;
  // The vertex where candidate k's two shortest paths meet (the cycle is s1 ... it ... s2).
  int meeting(int k) const { return found_.at(k).meeting; }
  // The gap bound G_i each seed's searches used, one per seed in seed order (infinity when
  // unbounded).
  const std::vector<double>& seed_limits() const { return seed_limits_; }

 private:
  using Arc = SegmentUnits::Arc;
  struct Found {
    int seed_slot;  // index of the seed's trees in parents_
    int meeting;    // where the path from s1 meets the path back to s2
  };
  // Dijkstra over units from unit `source` into distance_[tree], parent_arc_[tree] and
  // order_[tree] (settled units in order; settled_[tree] marks them with `stamp`); stops when
  // all units holding third vertices are settled (unit_third_ for tree 0, wanted_ for tree 1) or
  // nothing within `limit` is left: arcs u -> w with d(u) + weight > limit are not relaxed.
  // Returns the number of settled units.
  int shortest_paths(int tree, int source, int num_thirds, double limit, int stamp);
  // Splits the seed's unit into s1's and s2's (s2's takes the spare id num_units), blocks every
  // arc into them and gives both the arcs of their own vertex, the seed edge left out; the
  // arcs into them go on extra lists of their neighbours. close_seed undoes it.
  void open_seed(const SegmentGraph& graph, int seed, int s1, int s2);
  void close_seed(int s1, int s2);
  // The vertex by which the k-th unit settled in `tree` is entered (`root` for the first), its
  // parent set in `parent`.
  int entry_vertex(int tree, int k, int root, int* parent) const;
  void second_tree_pass(const Point* points, int s2, int settled, int* parent);
  void first_tree_pass(const Point* points, int s1, int settled, int slot, int* parent,
                       const int* parent2);

  int num_vertices_ = 0;
  int num_units_ = 0;          // units of the contraction; one more id is s2's during a seed
  std::vector<Point> points_;  // vertex positions relative to the current seed's s1
  SegmentUnits units_;
  // units_.arcs, then the open seed's arcs: from its two units, then into them.
  std::vector<Arc> arcs_;
  std::vector<int> unit_begin_, unit_end_;  // each unit's arcs in arcs_
  // Arcs into the open seed's units, per unit: a chain from extra_head_ through extra_next_.
  std::vector<int> extra_head_, extra_next_;
  std::vector<int> opened_by_;  // per unit: the seed that opens it, -1 none, -2 several
  std::vector<char> unit_third_;
  std::vector<char> wanted_;  // units of third vertices settled by the first tree
  int num_third_units_ = 0;
  std::vector<double> seed_limits_;
  // Per tree, per unit.
  std::vector<double> distance_[2];
  std::vector<int> parent_arc_[2];
  std::vector<int> order_[2];
  std::vector<int> settled_[2];  // the seed slot that last settled the unit
  // Per tree, per graph vertex: root-to-vertex sums of cross(parent, child).
  std::vector<double> shoelace_[2];
  std::vector<int> enter_, size_, next_;  // pre-order interval of the second (vertex) tree
  std::vector<double> bound_;             // largest d1 - d2 from s1 down the first tree
  // fork_[v]: the nearest vertex up the first tree from v (v itself included) whose two parents
  // differ: up to it, the paths from v to s1 and to s2 are the same.
  std::vector<int> fork_;
  // Far above the rounding error of any path length (a fraction 1e-9 of all weights).
  double tolerance_ = 0.0;
  std::vector<int> meeting_seen_;
  // Dijkstra's frontier: (distance, unit id) keys, unordered; frontier_position_[u] is u's
  // slot or -1. One spare slot past the end.
  std::vector<unsigned __int128> frontier_;
  std::vector<int> frontier_position_;
  std::vector<std::pair<int, double>> blocked_;  // arcs into the open seed's units, weights
  // Parent vertex per tree per seed: parents_[(2 * slot + tree) * n + v], -1 for the root;
  // only the vertices of settled units are written.
  std::vector<int> parents_;
  std::vector<int> seed_source_;  // s1, s2 per slot
  std::vector<CandidateSummary> candidates_;
  std::vector<Found> found_;
};

// For every sampled detected edge e_i = (s1, s2): block e_i, find shortest paths from s1 and s2,
// and for every other detected edge e_j close the cycle e_i + path(s1 -> v_j) + path(v_j -> s2)
// through its first endpoint v_j. Where the two paths merge before v_j, the shared tail is cut
// off so that every candidate is a cycle that visits each vertex once. A third vertex whose paths
// meet where an earlier one's did (same cycle) is skipped, as are cycles of fewer than three
// vertices; other repeats of a cycle can remain (they carry identical gap and, up to rounding,
// area). Runs CycleSearch (one per thread) and materialises every candidate.
std::vector<CycleCandidate> search_cycle_candidates(const SegmentGraph& graph,
                                                    const BdspOptions& options = {});

// The polygon of a candidate's vertices.
Polygon candidate_polygon(const SegmentGraph& graph, const CycleCandidate& candidate);

}  // namespace scbt
