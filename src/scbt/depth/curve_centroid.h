// The centre of a closed 3-D curve.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace scbt {

// Arc-length weighted centroid of the closed polyline through `points` (in order, the last
// joined to the first): sum over edges of length * midpoint / total length. It is the centre of
// the rim itself, unlike the mean of the vertices (biased towards densely sampled stretches) or
// of the depth inside it (a bowl's inside is lower than its rim). Non-finite points are skipped;
// a single point is its own centroid; no points give NaN.
Eigen::Vector3d closed_curve_centroid(const std::vector<Eigen::Vector3d>& points);

}  // namespace scbt
