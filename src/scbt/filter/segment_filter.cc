#include "scbt/filter/segment_filter.h"

#include "scbt/geometry/boundary_query.h"

namespace scbt {

double mean_distance_to_boundary(const Segment& segment, const Polygon& boundary) {
  return (distance_to_boundary(segment.a, boundary) + distance_to_boundary(segment.b, boundary) +
          distance_to_boundary(segment.midpoint(), boundary)) /
         3.0;
}

std::vector<Segment> filter_segments_near_boundary(const std::vector<Segment>& segments,
                                                   const Polygon& boundary,
                                                   double max_mean_distance) {
  std::vector<Segment> kept;
  filter_segments_near_boundary(segments, boundary, max_mean_distance, &kept);
  return kept;
}

void filter_segments_near_boundary(const std::vector<Segment>& segments, const Polygon& boundary,
                                   double max_mean_distance, std::vector<Segment>* kept,
                                   std::vector<double>* kept_distances) {
  kept->clear();
  if (kept_distances) kept_distances->clear();
  if (boundary.empty()) return;
  const BoundaryQuery edges(boundary);
  // Distances are non-negative, so a sum that already reaches 3x the bound cannot get below it.
  const double sum_bound = 3.0 * max_mean_distance;
  size_t hint = 0;
  for (const Segment& segment : segments) {
    const double da = edges.distance(segment.a, &hint);
    if (!(da < sum_bound)) continue;
    const double db = edges.distance(segment.b, &hint);
    if (!(da + db < sum_bound)) continue;
    const double dm = edges.distance(segment.midpoint(), &hint);
    if (!((da + db + dm) / 3.0 < max_mean_distance)) continue;
    kept->push_back(segment);
    if (kept_distances) kept_distances->insert(kept_distances->end(), {da, db, dm});
  }
}

}  // namespace scbt
