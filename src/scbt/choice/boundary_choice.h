// Stage 6: the tracking criterion (paper Eq. 1-2): the candidate of smallest grouping cost among
// those whose area is similar enough to the previous boundary's.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "scbt/choice/boundary_distance_cache.h"
#include "scbt/cycles/bdsp.h"
#include "scbt/geometry/shape_descriptor.h"

namespace scbt {

// Γ = |B_G| / area (Eq. 1). Infinite for a cycle without area. Inline (as area_similarity):
// the choice evaluates both for every candidate, hundreds per frame.
inline double grouping_cost(double gap_length, double area) {
  return area > 0.0 ? gap_length / area : std::numeric_limits<double>::infinity();
}

// S = min(A_p / A_c, A_c / A_p) (Eq. 2); 0 when either area is 0.
inline double area_similarity(double previous_area, double candidate_area) {
  if (!(previous_area > 0.0) || !(candidate_area > 0.0)) return 0.0;
  // One division: the smaller area over the larger is the minimum of the two ratios, to the
  // last bit (rounding is monotonic, so one ratio rounds to <= 1 and the other to >= 1).
  return candidate_area >= previous_area ? previous_area / candidate_area
                                         : candidate_area / previous_area;
}

struct BoundaryChoice {
  int index = -1;     // into the candidate list
  double cost = 0.0;  // grouping cost Γ of the chosen candidate
  double similarity = 0.0;
  int num_admissible = 0;  // candidates that passed the similarity gate
};

// The admissible candidate (similarity > min_similarity) of least cost Γ; ties go to the more
// similar one.
// std::nullopt when no candidate is admissible.
std::optional<BoundaryChoice> choose_boundary(const std::vector<CycleCandidate>& candidates,
                                              double previous_area, double min_similarity);

// How StableChooser ranks the candidates that pass the area gate, beyond the paper's Γ.
struct RankingWeights {
  // k: candidates are ranked by Γ / S^k (S: their area similarity, Eq. 2) instead of Γ alone; 0 is
  // the paper's rule. Γ = gap / area favours a larger cycle for its area alone (10 % larger, about
  // 9 % cheaper at the same gap), which lets a cycle creep outward frame by frame inside the gate;
  // S^k takes part of that back for any change of area.
  double similarity_exponent = 0.0;
  // w: and by exp(w d), d the shape_distance of their affine shape (affine_shape_descriptor) to
  // `shape_reference` less `shape_noise` (within 0 and 1). 0, or no valid reference, leaves the
  // ranking to Γ / S^k.
  double shape_weight = 0.0;
  const ShapeDescriptor* shape_reference = nullptr;
  // The distance that is the descriptor's own jitter, not a change of shape: the dataset's
  // ground-truth outlines lie 0.001-0.005 from their remembered shape (ShapeMemory) in the median,
  // at most 0.012 in 9 frames of 10. Below it the ranking is Γ / S^k's, so that the weight reorders
  // only clear changes of shape, not the near ties among outlines of one shape.
  double shape_noise = 0.02;
};

// The stabilised choice with its buffers and distance cache kept across frames, over any list
// of candidates that carry `gap_length` and `area`, whose cycles (graph vertex ids) are listed on
// demand by `list_vertices(index, std::vector<int>* out)`: only near-tied candidates are ever
// listed. Chooses exactly as the straightforward choose_boundary_stable
// (reference/plain_choice.h) does, distances equal up to rounding.
// `known` (optional): distances to `previous` already computed for the graph's segments.
// `gate_area` (when > 0): the area the gate compares candidates with instead of `previous`'s.
// `weights`: the ranking (the paper's Γ alone by default); near ties are those within
// (1 + tolerance) of the least weighted cost.
class StableChooser {
 public:
  template <class Candidate, class ListVertices>
  std::optional<BoundaryChoice> choose(const std::vector<Candidate>& candidates,
                                       ListVertices&& list_vertices, const SegmentGraph& graph,
                                       const Polygon& previous, double min_similarity,
                                       double tolerance,
                                       const KnownSegmentDistances* known = nullptr,
                                       double gate_area = 0.0, const RankingWeights& weights = {});

 private:
  struct NearTie {
    int index;             // into the candidates
    int rank;              // position in (area, gap) order: the tie-break between equal distances
    double from_distance;  // cycle -> previous, a lower bound of the boundary distance
    int begin, end;        // its cycle in `cycles_`
  };
  // Picks among the near_ties_ (filled, cycles listed, from_distance set) that `accepts(tie)`
  // (called with the tie's cycle in cycle_, only for those whose distance could still win);
  // returns the candidate index, -1 if no accepted distance is finite.
  template <class Accepts>
  int closest_near_tie(Accepts&& accepts);
  // exp(w d) for cycle_ (RankingWeights::shape_weight).
  double shape_factor(const SegmentGraph& graph, const RankingWeights& weights);

  std::vector<double> admissible_cost_;
  // A near tie's sort key next to its index, so that the sort reads one array.
  struct Keyed {
    double area, gap_length;
    int index;
  };
  std::vector<Keyed> order_;
  std::vector<NearTie> near_ties_;
  std::vector<int> cycles_;
  std::vector<int> cycle_edges_;  // per entry of cycles_, the edge ending there (edge_between)
  std::vector<int> cycle_;
  BoundaryDistanceCache cache_;
  // The distinct cycles within the bound, with their cost (weighted once weighed).
  struct Weighed {
    int index, rank;  // rank: position in (area, gap) order
    double cost;
  };
  std::vector<Weighed> weighed_;
  Polygon outline_;  // shape_factor's
};

template <class Candidate, class ListVertices>
std::optional<BoundaryChoice> StableChooser::choose(
    const std::vector<Candidate>& candidates, ListVertices&& list_vertices,
    const SegmentGraph& graph, const Polygon& previous, double min_similarity, double tolerance,
    const KnownSegmentDistances* known, double gate_area, const RankingWeights& weights) {
  const double similarity_exponent = weights.similarity_exponent;
  const double previous_area = gate_area > 0.0 ? gate_area : area(previous);
  BoundaryChoice best;
  // Each candidate's cost, kept for the near-tie pass below (NaN: not admissible, so that no
  // comparison admits it), so that the divisions are done once per candidate (hundreds of
  // candidates per frame).
  admissible_cost_.resize(candidates.size());
  for (int i = 0; i < static_cast<int>(candidates.size()); ++i) {
    admissible_cost_[i] = std::numeric_limits<double>::quiet_NaN();
    const double similarity = area_similarity(previous_area, candidates[i].area);
    if (!(similarity > min_similarity)) continue;
    ++best.num_admissible;
    double cost = grouping_cost(candidates[i].gap_length, candidates[i].area);
    // The default's square root is several times cheaper than pow (hundreds of candidates).
    if (similarity_exponent == 0.5) {
      cost /= std::sqrt(similarity);
    } else if (similarity_exponent > 0.0) {
      cost /= std::pow(similarity, similarity_exponent);
    }
    admissible_cost_[i] = cost;
    if (best.index < 0 || cost < best.cost || (cost == best.cost && similarity > best.similarity)) {
      best.index = i;
      best.cost = cost;
      best.similarity = similarity;
    }
  }
  if (best.index < 0) return std::nullopt;
  if (tolerance <= 0.0) return best;
  const bool weigh_shape =
      weights.shape_weight > 0.0 && weights.shape_reference && weights.shape_reference->valid;
  // A weighted cost is at least the cost, and the least weighted cost at most the best's: no
  // candidate dearer than (1 + tolerance) times the best's weighted cost can tie.
  double bound = best.cost * (1.0 + tolerance);
  double best_factor = 1.0;
  if (weigh_shape) {
    list_vertices(best.index, &cycle_);
    best_factor = shape_factor(graph, weights);
    bound *= best_factor;
  }
  // The best's shape within the jitter (the usual case): the least weighted cost is its cost, and
  // a candidate ties when its cost times its factor is within (1 + tolerance) of it, which needs
  // its factor only once the distance order reaches it. Otherwise every cycle that could tie is
  // weighed first.
  const bool weigh_lazily = weigh_shape && best_factor == 1.0;
  const bool weigh_first = weigh_shape && !weigh_lazily;

  order_.clear();
  for (int i = 0; i < static_cast<int>(candidates.size()); ++i) {
    if (admissible_cost_[i] <= bound) {
      order_.push_back({candidates[i].area, candidates[i].gap_length, i});
    }
  }
  // Different seeds often close the same cycle; identical cycles have bit-identical gap and
  // area, so each (area, gap) pair is measured once. (The sort sees the same sequence and the
  // same comparisons as one of indices compared through the candidates, so equal keys end in
  // the same order.)
  std::sort(order_.begin(), order_.end(), [](const Keyed& a, const Keyed& b) {
    return a.area < b.area || (a.area == b.area && a.gap_length < b.gap_length);
  });
  // The distinct cycles, cheapest first: a weighted cost is at least the cost, so once a cost
  // exceeds (1 + tolerance) times the least weighted cost so far, neither it nor any dearer one can
  // tie, and their shapes need not be described.
  weighed_.clear();
  for (size_t k = 0; k < order_.size(); ++k) {
    const Keyed& c = order_[k];
    if (k > 0) {
      const Keyed& before = order_[k - 1];
      if (before.area == c.area && before.gap_length == c.gap_length) continue;
    }
    weighed_.push_back({c.index, static_cast<int>(k), admissible_cost_[c.index]});
  }
  if (weigh_first) {
    std::sort(weighed_.begin(), weighed_.end(), [](const Weighed& a, const Weighed& b) {
      return a.cost < b.cost || (a.cost == b.cost && a.rank < b.rank);
    });
  }
  double least = std::numeric_limits<double>::infinity();
  int least_index = best.index, least_rank = 0;
  size_t num_weighed = 0;
  for (; num_weighed < weighed_.size(); ++num_weighed) {
    Weighed& w = weighed_[num_weighed];
    if (weigh_first) {
      if (w.cost > least * (1.0 + tolerance)) break;
      list_vertices(w.index, &cycle_);
      w.cost *= w.index == best.index ? best_factor : shape_factor(graph, weights);
    }
    // Equal weighted costs: the earlier in (area, gap) order, as a scan in that order would.
    if (w.cost < least || (w.cost == least && w.rank < least_rank)) {
      least = w.cost;
      least_index = w.index;
      least_rank = w.rank;
    }
  }
  weighed_.resize(num_weighed);
  near_ties_.clear();
  cycles_.clear();
  cache_.reset(graph, previous, known);
  cycle_edges_.clear();
  for (const Weighed& w : weighed_) {
    if (!(w.cost <= least * (1.0 + tolerance))) continue;
    list_vertices(w.index, &cycle_);
    // The cycle's edges are found once, here, and kept for the other direction.
    NearTie tie{w.index, w.rank, cache_.mean_distance_from_cycle(cycle_, &cycle_edges_),
                static_cast<int>(cycles_.size()), 0};
    cycles_.insert(cycles_.end(), cycle_.begin(), cycle_.end());
    tie.end = static_cast<int>(cycles_.size());
    near_ties_.push_back(tie);
  }
  const double tie_bound = least * (1.0 + tolerance);
  const int closest = weigh_lazily ? closest_near_tie([&](const NearTie& tie) {
    return admissible_cost_[tie.index] * shape_factor(graph, weights) <= tie_bound;
  })
                                   : closest_near_tie([](const NearTie&) { return true; });
  if (closest >= 0) {
    best.index = closest;
  } else if (weigh_first) {
    best.index = least_index;
  } else if (weigh_lazily) {
    // No finite distance (rare): the least weighted cost, the earlier in (area, gap) order. (Here
    // every distinct cycle is a near tie, its cycle listed in cycles_.)
    double least_weighted = std::numeric_limits<double>::infinity();
    int least_weighted_rank = 0;
    for (const NearTie& tie : near_ties_) {
      cycle_.assign(cycles_.begin() + tie.begin, cycles_.begin() + tie.end);
      const double cost = admissible_cost_[tie.index] * shape_factor(graph, weights);
      if (cost < least_weighted || (cost == least_weighted && tie.rank < least_weighted_rank)) {
        least_weighted = cost;
        least_weighted_rank = tie.rank;
        best.index = tie.index;
      }
    }
  }
  const Candidate& chosen = candidates[best.index];
  best.cost = grouping_cost(chosen.gap_length, chosen.area);
  best.similarity = area_similarity(previous_area, chosen.area);
  return best;
}

template <class Accepts>
int StableChooser::closest_near_tie(Accepts&& accepts) {
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
    if (!accepts(tie)) continue;
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
