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

double StableChooser::shape_factor(const SegmentGraph& graph, const RankingWeights& weights) {
  // The descriptor samples the outline from its first vertex: one cycle closed from different
  // seeds (another start or direction) is described from one start and direction, so that it is
  // weighed the same whichever copy the choice meets.
  const int n = static_cast<int>(cycle_.size());
  int start = 0;
  Point s = n > 0 ? graph.vertices[cycle_[0]] : Point();
  for (int i = 1; i < n; ++i) {
    const Point& p = graph.vertices[cycle_[i]];
    if (p.y < s.y || (p.y == s.y && p.x < s.x)) {
      start = i;
      s = p;
    }
  }
  // From `start` to the end, then from the first vertex up to it.
  outline_.resize(static_cast<size_t>(n));
  Point* out = outline_.data();
  for (int i = start; i < n; ++i) *out++ = graph.vertices[cycle_[i]];
  for (int i = 0; i < start; ++i) *out++ = graph.vertices[cycle_[i]];
  if (signed_area(outline_) < 0.0) std::reverse(outline_.begin() + 1, outline_.end());
  const double distance =
      shape_distance(affine_shape_descriptor(outline_), *weights.shape_reference);
  const double change = std::clamp(distance - weights.shape_noise, 0.0, 1.0);
  return std::exp(weights.shape_weight * change);
}

}  // namespace scbt
