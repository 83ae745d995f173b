// Stage 5: Bidirectional Shortest Path cycle candidates (paper §III-D, Fig. 4e, Algorithm 1).
#pragma once

#include <utility>
#include <vector>

#include "scbt/geometry/polygon.h"
#include "scbt/grouping/segment_graph.h"
#include "scbt/grouping/segment_units.h"

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
  // Search with the generic-graph baseline (search_cycle_candidates_generic: Boost.Graph's
  // Dijkstra, every candidate materialised) instead of CycleSearch: the straightforward
  // configuration, for benchmarks only. Same candidates up to shortest-path ties.
  bool generic_graph = false;

  // Throws std::invalid_argument naming a bad value (seed_stride < 1).
  void check() const;
};

// What the boundary choice (StableChooser, boundary_choice.h) will do with the candidates, so
// that CycleSearch can skip work that cannot change its choice. The choice admits candidates of
// area similarity min(A_p / A_c, A_c / A_p) > min_similarity, takes the least grouping cost
// Γ* = gap / area among them and, with a tolerance, every admissible candidate of
// Γ <= Γ* (1 + tolerance) as a near tie.
struct CandidateGate {
  double previous_area = 0.0;   // A_p, the previous boundary's area
  double min_similarity = 0.9;  // as TrackerOptions::min_area_similarity
  double tolerance = 0.1;       // as TrackerOptions::cost_tolerance (0: only the least Γ)

  // Throws std::invalid_argument naming a bad value: previous_area not finite and > 0,
  // min_similarity outside [0, 1], tolerance negative or not finite.
  void check() const;
  // The largest admissible area, A_p / min_similarity (infinity for min_similarity 0).
  double max_area() const;
};

// What the boundary choice needs of a candidate; its vertices are listed on demand
// (CycleSearch::vertices).
struct CandidateSummary {
  double gap_length = 0.0;  // |B_G|, as in CycleCandidate
  double area = 0.0;        // enclosed area, as in CycleCandidate (to ~1e-9 relative)
  int seed_edge = -1;       // the detected edge e_i the cycle was grown from
};

// The BDSP search of search_cycle_candidates, without materialising candidates: each candidate
// is a summary (gap, area, seed) plus the meeting vertex of its two shortest paths, and the
// search keeps each seed's two shortest-path trees (parent arrays) so that the vertices of any
// candidate can be listed afterwards. What makes it fast, each tested against the
// straightforward search:
//  - Dijkstra runs over contracted segments (segment_units.h): both ends of a detected segment
//    are one node, parallel edges between two nodes are one arc (the lightest), so each search
//    settles about half as many nodes. The seed's segment is split back into s1 and s2 for its
//    two searches, its arcs taken from the vertices. Each node's entry vertex hangs from the
//    vertex its parent arc leaves, the segment's other end from the entry: the trees over graph
//    vertices, shortest-path trees like the vertex search's. Where path lengths tie they can
//    pick other shortest paths than a vertex search (then other, equally valid, candidates);
//    without ties they are the same trees and the candidates are the same, in the same order;
//  - the area comes from root-to-vertex sums of shoelace terms along each tree, not a walk;
//  - the meeting vertex is where the two trees' parents first differ up from the third vertex
//    (precomputed per seed), plus a walk above it cut short by a bound on d1 - d2 (the paths can
//    meet again only where rounded path lengths tie differently from the two roots);
//  - Dijkstra keeps its frontier (about a dozen nodes) as an unordered array of 128-bit
//    (distance, id) keys scanned for the least and stops once every third vertex is settled;
//  - arcs that a strictly shorter two-arc detour makes useless to every search are left out
//    (drop_dominated_arcs);
//  - nothing is allocated once the buffers have grown to the graph's size.
// options.generic_graph is ignored here. Not thread-safe; use one object per thread.
//
// With a CandidateGate (run's `gate`), the search keeps only candidates the gated choice can
// pick, and bounds its Dijkstras (exact rule, tested):
//  - Seeds are searched in order; before seed i, Γ_i is the least Γ of the admissible candidates
//    kept from seeds 0..i-1 (infinity before any), and the seed's gap bound is
//    G_i = (1 + tolerance) Γ_i max_area() (1 + 1e-9) (seed_limits()[i]; infinity while Γ_i is).
//    A near tie has gap = Γ area <= (1 + tolerance) Γ* max_area() <= G_i.
//  - Both Dijkstras of seed i settle only nodes within G_i of their root: an arc u -> w is not
//    relaxed when d(u) + weight > G_i (arcs are sorted by weight, so the loop ends there).
//    Distances and parents of the vertices within G_i are the unbounded search's, bit for bit
//    (ties included: the frontier order is (distance, id), whatever was left out).
//  - So seed i yields the unbounded candidates whose third vertex lies within G_i of both s1
//    and s2 (the repeat-of-a-cycle skip then only sees those thirds), filtered: a candidate is
//    kept iff it is admissible and Γ <= Γ_best (1 + tolerance), Γ_best the least admissible Γ
//    kept before it (in list order), computed with the chooser's own expressions.
//  - The loss: a cycle whose gap is within G_i but whose every third vertex lies beyond G_i
//    (the two paths share a long tail) is not found. The chooser's result can then differ from
//    the unbounded one; the test measures how often on random graphs.
//  - The order is the unbounded search's but for cycles first met from a third vertex the bound
//    left out (then listed where a later third meets them). num_admissible of the choice then
//    counts the kept candidates only (the ones that can be near ties), not all admissible ones.
// Both Dijkstras stop once the third vertices settled by the first are settled (either way).
class CycleSearch {
 public:
  // Throws std::invalid_argument for bad options (BdspOptions::check, CandidateGate::check).
  // gate == nullptr: every candidate, unbounded searches (as search_cycle_candidates).
  void run(const SegmentGraph& graph, const BdspOptions& options = {},
           const CandidateGate* gate = nullptr);

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
// area). Runs CycleSearch (one per thread) and materialises every candidate, or, when
// options.generic_graph is set, search_cycle_candidates_generic.
std::vector<CycleCandidate> search_cycle_candidates(const SegmentGraph& graph,
                                                    const BdspOptions& options = {});

// The polygon of a candidate's vertices.
Polygon candidate_polygon(const SegmentGraph& graph, const CycleCandidate& candidate);

}  // namespace scbt
