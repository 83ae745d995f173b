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
    const double cost = grouping_cost(candidates[i].gap_length, candidates[i].area);
    if (best.index < 0 || cost < best.cost || (cost == best.cost && similarity > best.similarity)) {
      best.index = i;
      best.cost = cost;
      best.similarity = similarity;
    }
  }
  if (best.index < 0) return std::nullopt;
  return best;
}

}  // namespace scbt
