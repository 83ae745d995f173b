// Test support: the random inputs the graph, cycle-search and reference tests share. Linked only
// by tests (library scbt_random_graphs).
#pragma once

#include <functional>
#include <random>
#include <vector>

#include "scbt/geometry/polygon.h"
#include "scbt/graph/segment_graph.h"

namespace scbt {

// True when the segments cross at a point inside both (touching or sharing an endpoint is not
// crossing).
bool properly_cross(const Segment& s, const Segment& t);

// Up to `count` short segments (5-50 px) in a 300 px square, none properly crossing an earlier
// one (as a line detector's would not). With `share_endpoints`, about one in four starts where an
// earlier one ends: zero-weight paths of several segments, and ties in path length.
std::vector<Segment> random_segments(std::mt19937& rng, int count, bool share_endpoints);

// A random multigraph (no graph geometry, no self-loops) of `n` vertices in a 100 px square and
// `m` edges, about one in four detected (weight 0); the others weigh `gap_weight(rng)`.
SegmentGraph random_multigraph(std::mt19937& rng, int n, int m,
                               const std::function<double(std::mt19937&)>& gap_weight);

}  // namespace scbt
