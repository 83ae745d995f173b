// Ratio contour grouping (Wang, Kubota, Siskind & Wang 2005; Stahl & Wang 2007), the paper's "RRC"
// baseline: among the alternate cycles of the segment graph (cycles that alternate detected
// segments and gap-filling segments), find the one of least ratio R = |B_G| / area, gap length
// over enclosed area.
//
// How it is solved here. Each detected segment is used in both directions ("oriented copies").
// A copy has a tail and a head vertex joined by a solid edge; a dashed edge joins the head of one
// copy to the tail of a copy of another segment when their endpoints coincide (gap 0) or are
// joined by a generated (Delaunay gap-filling) edge of the segment graph (gap = its length). This
// auxiliary graph is bipartite (tails | heads), and its perfect matchings are exactly the sets of
// vertex-disjoint oriented alternate cycles: the matching made of all solid edges is the empty
// set, and M (+) solids is a set of alternate cycles for any other perfect matching M. With the
// signed area of every oriented edge taken as the triangle it spans with a reference point (so a
// cycle's edges sum to its signed enclosed area, Green's theorem), the cycle cost
// gap - lambda * area is a sum of edge costs, and a minimum-weight perfect matching, solved
// exactly as an assignment problem (Hungarian method), gives the set of cycles of least total
// cost. The ratio is minimised by Dinkelbach's parametric search: lambda <- ratio of the best
// cycle found, until no cycle has negative cost.
//
// Deviation, stated plainly: orientation makes the area term well defined, but an alternate cycle
// of the oriented graph may traverse one segment in both directions or revisit an endpoint
// (a non-simple boundary). The optimum over all alternate cycles is computed exactly; the answer
// returned is the least-ratio *simple* cycle among those met during the search, which is the
// global optimum whenever that optimum is simple (flagged in `optimal`).
// Boost 1.74's general maximum_weighted_matching is not used: the auxiliary graph is bipartite, and
// that Boost version has known wrong-result / non-termination bugs (boostorg/graph#399, #223).
#pragma once

#include <optional>

#include "scbt/geometry/polygon.h"
#include "scbt/graph/segment_graph.h"

namespace scbt {

struct RatioContourOptions {
  // Dinkelbach's search starts from this ratio (1/pixel): cycles of larger ratio are never
  // considered. 1 is far above any useful boundary (a 100x100 region with 100 px of gaps: 0.01).
  double initial_ratio = 1.0;
  int max_iterations = 20;
  // Cycles enclosing less than this (pixels^2) are ignored when picking the answer.
  double min_area = 16.0;

  void check() const;
};

struct RatioContour {
  Polygon polygon;
  double gap_length = 0.0;
  double area = 0.0;
  double ratio = 0.0;    // gap_length / area
  int iterations = 0;    // matchings solved
  bool optimal = false;  // the least-ratio alternate cycle overall is this (simple) one
  // The least ratio over all alternate cycles of the oriented graph, simple or not, when the
  // search converged within max_iterations (else the last bound reached).
  double optimum_ratio = 0.0;
};

// `reference` is the point the edge areas are measured from (any point gives the same cycle
// areas; one near the segments keeps the numbers small). std::nullopt when the graph has no
// simple alternate cycle of ratio below options.initial_ratio.
std::optional<RatioContour> find_ratio_contour(const SegmentGraph& graph, const Point& reference,
                                               const RatioContourOptions& options = {});

// Minimum-cost perfect assignment of an n x n cost matrix (row-major, entries may be +infinity
// for forbidden pairs as long as a finite assignment exists). Returns column of each row.
std::vector<int> solve_assignment(const std::vector<double>& cost, int n);

}  // namespace scbt
