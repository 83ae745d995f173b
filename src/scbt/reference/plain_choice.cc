#include "scbt/reference/plain_choice.h"

#include <algorithm>

#include "scbt/geometry/polygon.h"

namespace scbt {
namespace {

// Length-weighted mean distance from the closed polyline `from` to the closed polyline `to`,
// by Simpson's rule on each edge of `from` (endpoints and midpoint).
double mean_polyline_distance(const Polygon& from, const Polygon& to) {
  const size_t n = from.size();
  double weighted = 0.0, total_length = 0.0;
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point& a = from[j];
    const Point& b = from[i];
    const double length = cv::norm(b - a);
    weighted += length *
                (distance_to_boundary(a, to) + 4.0 * distance_to_boundary((a + b) * 0.5, to) +
                 distance_to_boundary(b, to)) /
                6.0;
    total_length += length;
  }
  return total_length > 0.0 ? weighted / total_length : 0.0;
}

}  // namespace

double boundary_distance(const Polygon& a, const Polygon& b) {
  return std::max(mean_polyline_distance(a, b), mean_polyline_distance(b, a));
}

std::optional<BoundaryChoice> choose_boundary_stable(const std::vector<CycleCandidate>& candidates,
                                                     const SegmentGraph& graph,
                                                     const Polygon& previous, double min_similarity,
                                                     double tolerance, double similarity_exponent) {
  StableChooser chooser;
  return chooser.choose(
      candidates, [&](int index, std::vector<int>* cycle) { *cycle = candidates[index].vertices; },
      graph, previous, min_similarity, tolerance, nullptr, 0.0, {similarity_exponent});
}

}  // namespace scbt
