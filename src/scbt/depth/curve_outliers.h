// Depth outliers along a closed boundary: a sample whose depth breaks the curve's local trend.
#pragma once

#include <vector>

#include "scbt/depth/depth_options.h"

namespace scbt {

// Sets to 0 every depth (metres; 0 = missing) that agrees with neither side of the curve: on
// each side a straight line is fitted robustly (Theil-Sen over the index) to the nearest
// options.neighbour_span (at most 16) valid depths and extrapolated to the sample; the depth is
// kept when it is within surface_tolerance of either prediction, or when neither side has 2 valid
// depths. One side suffices so that a corner (a kink in the depth profile) survives. The depths are
// treated as a closed sequence.
void reject_curve_outliers(const DepthOptions& options, std::vector<double>* depths);

}  // namespace scbt
