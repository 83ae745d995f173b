// Initialisation from a box: users rarely have the object's polygon at hand, but can draw a box
// around it. The boundary to track is then the most salient closed boundary inside the box: the
// cycle of least grouping cost Γ (Eq. 1) among the segments detected there.
#pragma once

#include <optional>
#include <vector>

#include "scbt/cycles/bdsp.h"
#include "scbt/geometry/polygon.h"

namespace scbt {

// A cycle counts only if it encloses at least this share of the box: the object is what the box
// was drawn around, not a speck of texture inside it (a closed speck has Γ = 0 too).
constexpr double kMinBoxAreaShare = 0.1;

// The least-Γ BDSP cycle of `segments` (ties: the larger area) among those enclosing at least
// `min_area`; std::nullopt when there is none.
std::optional<Polygon> most_salient_boundary(const std::vector<Segment>& segments, double min_area,
                                             const BdspOptions& options = {});

}  // namespace scbt
