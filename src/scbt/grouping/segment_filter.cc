#include "scbt/grouping/segment_filter.h"

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
  for (const Segment& segment : segments) {
    if (mean_distance_to_boundary(segment, boundary) < max_mean_distance) kept.push_back(segment);
  }
  return kept;
}

}  // namespace scbt
