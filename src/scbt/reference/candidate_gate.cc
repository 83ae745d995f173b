#include "scbt/reference/candidate_gate.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "scbt/choice/boundary_choice.h"

namespace scbt {

void CandidateGate::check() const {
  if (!(previous_area > 0.0) || !std::isfinite(previous_area)) {
    throw std::invalid_argument("candidate gate previous_area must be finite and positive, got " +
                                std::to_string(previous_area));
  }
  if (!(min_similarity >= 0.0 && min_similarity <= 1.0)) {
    throw std::invalid_argument("candidate gate min_similarity must be in [0, 1], got " +
                                std::to_string(min_similarity));
  }
  if (!(tolerance >= 0.0) || !std::isfinite(tolerance)) {
    throw std::invalid_argument("candidate gate tolerance must be finite and >= 0, got " +
                                std::to_string(tolerance));
  }
}

double CandidateGate::max_area() const {
  return min_similarity > 0.0 ? previous_area / min_similarity
                              : std::numeric_limits<double>::infinity();
}

void CandidateGate::start() {
  check();
  best_cost_ = std::numeric_limits<double>::infinity();
}

double CandidateGate::gap_limit() const {
  if (!std::isfinite(best_cost_)) return std::numeric_limits<double>::infinity();
  // The slack covers rounding.
  return best_cost_ > 0.0 ? (1.0 + tolerance) * best_cost_ * max_area() * (1.0 + 1e-9) : 0.0;
}

bool CandidateGate::keep(const CandidateSummary& c) {
  // What StableChooser::choose computes: a candidate not admissible, or costlier than
  // (1 + tolerance) times a cost already found (>= the least one), is never a near tie.
  if (!(area_similarity(previous_area, c.area) > min_similarity)) return false;
  const double cost = grouping_cost(c.gap_length, c.area);
  if (cost > best_cost_ * (1.0 + tolerance)) return false;
  best_cost_ = std::min(best_cost_, cost);
  return true;
}

}  // namespace scbt
