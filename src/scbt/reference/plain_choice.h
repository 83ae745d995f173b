// The stabilised boundary choice written the straightforward way, on materialised candidates and
// whole polygons: what StableChooser (choice/boundary_choice.h) is tested and measured against.
#pragma once

#include <optional>
#include <vector>

#include "scbt/choice/boundary_choice.h"
#include "scbt/cycles/bdsp.h"
#include "scbt/geometry/polygon.h"
#include "scbt/graph/segment_graph.h"

namespace scbt {

// Symmetric mean distance between two closed boundaries, in the spirit of E_AL but computed on
// the polylines: the larger of the length-weighted mean distances from each to the other.
double boundary_distance(const Polygon& a, const Polygon& b);

// Stabilised choice: among admissible candidates whose cost Γ is within (1 + tolerance) of the
// least one, the one closest to the previous boundary (boundary_distance). Near-ties in
// saliency are common (inner and outer rim of a cup, a spike through a stray segment); picking
// the one that moved least keeps the boundary from ratcheting outwards. tolerance 0 is the
// paper's rule. `similarity_exponent`: as StableChooser's.
std::optional<BoundaryChoice> choose_boundary_stable(const std::vector<CycleCandidate>& candidates,
                                                     const SegmentGraph& graph,
                                                     const Polygon& previous, double min_similarity,
                                                     double tolerance,
                                                     double similarity_exponent = 0.0);

}  // namespace scbt
