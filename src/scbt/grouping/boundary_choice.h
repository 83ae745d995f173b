// Stage 6: the tracking criterion (paper Eq. 1-2): the candidate of smallest grouping cost among
// those whose area is similar enough to the previous boundary's.
#pragma once

#include <optional>
#include <vector>

#include "scbt/grouping/bdsp.h"

namespace scbt {

// Γ = |B_G| / area (Eq. 1). Infinite for a cycle without area.
double grouping_cost(double gap_length, double area);

// S = min(A_p / A_c, A_c / A_p) (Eq. 2); 0 when either area is 0.
double area_similarity(double previous_area, double candidate_area);

struct BoundaryChoice {
  int index = -1;     // into the candidate list
  double cost = 0.0;  // grouping cost Γ of the chosen candidate
  double similarity = 0.0;
  int num_admissible = 0;  // candidates that passed the similarity gate
};

// The admissible candidate (similarity > min_similarity) of least cost Γ; ties go to the more
// similar one.
// std::nullopt when no candidate is admissible.
std::optional<BoundaryChoice> choose_boundary(const std::vector<CycleCandidate>& candidates,
                                              double previous_area, double min_similarity);

// Symmetric mean distance between two closed boundaries, in the spirit of E_AL but computed on
// the polylines: the larger of the length-weighted mean distances from each to the other.
double boundary_distance(const Polygon& a, const Polygon& b);

// Stabilised choice: among admissible candidates whose cost Γ is within (1 + tolerance) of the
// least one, the one closest to the previous boundary (boundary_distance). Near-ties in
// saliency are common (inner and outer rim of a cup, a spike through a stray segment); picking
// the one that moved least keeps the boundary from ratcheting outwards. tolerance 0 is the
// paper's rule.
std::optional<BoundaryChoice> choose_boundary_stable(const std::vector<CycleCandidate>& candidates,
                                                     const SegmentGraph& graph,
                                                     const Polygon& previous, double min_similarity,
                                                     double tolerance);

}  // namespace scbt
