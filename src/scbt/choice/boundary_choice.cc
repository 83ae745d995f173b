#include "scbt/choice/boundary_choice.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace scbt {

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

int StableChooser::closest_near_tie() {
  // The boundary distance is the larger of two means, so the cheap one (cycle -> previous,
  // cached per vertex and edge) bounds it from below: candidates are visited by that bound and
  // the expensive direction is computed only while the bound can still win.
  std::sort(near_ties_.begin(), near_ties_.end(), [](const NearTie& l, const NearTie& r) {
    return l.from_distance < r.from_distance ||
           (l.from_distance == r.from_distance && l.rank < r.rank);
  });
  double best_distance = std::numeric_limits<double>::infinity();
  int best_rank = std::numeric_limits<int>::max(), best_index = -1;
  for (const NearTie& tie : near_ties_) {
    if (tie.from_distance > best_distance) break;
    cycle_.assign(cycles_.begin() + tie.begin, cycles_.begin() + tie.end);
    const double distance = std::max(
        tie.from_distance, cache_.mean_distance_to_cycle(cycle_, &cycle_edges_[tie.begin]));
    // Equal distances go to the earlier in (area, gap) order, as a scan in that order would.
    if (distance < best_distance ||
        (distance == best_distance && std::isfinite(distance) && tie.rank < best_rank)) {
      best_distance = distance;
      best_rank = tie.rank;
      best_index = tie.index;
    }
  }
  return best_index;
}

}  // namespace scbt
