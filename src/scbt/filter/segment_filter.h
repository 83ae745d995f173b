// Stage 2: keep the detected segments that lie near the previous boundary (paper §III-A).
#pragma once

#include <vector>

#include "scbt/geometry/polygon.h"

namespace scbt {

// Mean distance from the segment's two endpoints and its midpoint to the closed boundary.
double mean_distance_to_boundary(const Segment& segment, const Polygon& boundary);

// Segments whose mean_distance_to_boundary is strictly below `max_mean_distance`, in input order.
std::vector<Segment> filter_segments_near_boundary(const std::vector<Segment>& segments,
                                                   const Polygon& boundary,
                                                   double max_mean_distance);
// The same into *kept (its buffer reused). When `kept_distances` is given, it receives the
// distances to the boundary of each kept segment's a, b and midpoint, three per segment: the
// boundary choice asks for the same points' distances again (KnownSegmentDistances).
void filter_segments_near_boundary(const std::vector<Segment>& segments, const Polygon& boundary,
                                   double max_mean_distance, std::vector<Segment>* kept,
                                   std::vector<double>* kept_distances = nullptr);

}  // namespace scbt
