#include "scbt/grouping/boundary_choice.h"

#include <algorithm>
#include <limits>

namespace scbt {

double grouping_cost(double gap_length, double area) {
  return area > 0.0 ? gap_length / area : std::numeric_limits<double>::infinity();
}

double area_similarity(double previous_area, double candidate_area) {
  if (!(previous_area > 0.0) || !(candidate_area > 0.0)) return 0.0;
  return std::min(previous_area / candidate_area, candidate_area / previous_area);
}

std::optional<BoundaryChoice> choose_boundary(const std::vector<CycleCandidate>& candidates,
                                              double previous_area, double min_similarity) {
  BoundaryChoice best;
  for (int i = 0; i < static_cast<int>(candidates.size()); ++i) {
    const double similarity = area_similarity(previous_area, candidates[i].area);
    if (!(similarity > min_similarity)) continue;
    ++best.num_admissible;
    const CycleCandidate& c = candidates[i];
    const double cost = grouping_cost(c.gap_length, c.area);
    if (best.index < 0 || cost < best.cost || (cost == best.cost && similarity > best.similarity)) {
      best.index = i;
      best.cost = cost;
      best.similarity = similarity;
    }
  }
  if (best.index < 0) return std::nullopt;
  return best;
}

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
                                                     double tolerance) {
  const double previous_area = area(previous);
  std::optional<BoundaryChoice> best = choose_boundary(candidates, previous_area, min_similarity);
  if (!best || tolerance <= 0.0) return best;
  const double bound = best->cost * (1.0 + tolerance);

  // Different seeds often close the same cycle; identical cycles have bit-identical gap and
  // area, so measuring each (gap, area) pair once avoids most distance computations.
  std::vector<int> near_ties;
  for (int i = 0; i < static_cast<int>(candidates.size()); ++i) {
    const CycleCandidate& c = candidates[i];
    if (!(area_similarity(previous_area, c.area) > min_similarity)) continue;
    if (grouping_cost(c.gap_length, c.area) <= bound) near_ties.push_back(i);
  }
  std::sort(near_ties.begin(), near_ties.end(), [&](int l, int r) {
    const CycleCandidate &a = candidates[l], &b = candidates[r];
    return a.area < b.area || (a.area == b.area && a.gap_length < b.gap_length);
  });
  double best_distance = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < near_ties.size(); ++k) {
    const CycleCandidate& c = candidates[near_ties[k]];
    if (k > 0) {
      const CycleCandidate& before = candidates[near_ties[k - 1]];
      if (before.area == c.area && before.gap_length == c.gap_length) continue;
    }
    const double distance = boundary_distance(candidate_polygon(graph, c), previous);
    if (distance < best_distance) {
      best_distance = distance;
      best->index = near_ties[k];
      best->cost = grouping_cost(c.gap_length, c.area);
      best->similarity = area_similarity(previous_area, c.area);
    }
  }
  return best;
}

}  // namespace scbt
