// A CandidatePruner that keeps only the candidates the stabilised choice can pick (for tests and
// benchmarks of CycleSearch's bounded mode; the tracker searches unbounded).
#pragma once

#include <limits>

#include "scbt/cycles/bdsp.h"

namespace scbt {

// What the boundary choice (StableChooser) will do with the candidates: it admits candidates of
// area similarity S > min_similarity (Eq. 2), takes the least grouping cost Γ* = gap / area
// (Eq. 1) among them and, with a tolerance, every admissible Γ <= Γ* (1 + tolerance) as a near
// tie. Before seed i the gap bound is G_i = (1 + tolerance) Γ_i max_area() (1 + 1e-9), Γ_i the
// least admissible Γ kept so far (infinity before any): a near tie has gap = Γ area <= G_i. The
// loss: a cycle within G_i whose every third vertex lies beyond G_i (the two paths share a long
// tail) is not found; the tests measure how often on random graphs. num_admissible of the choice
// then counts the kept candidates only.
class CandidateGate : public CandidatePruner {
 public:
  double previous_area = 0.0;   // A_p, the previous boundary's area
  double min_similarity = 0.9;  // as TrackerOptions::min_area_similarity
  double tolerance = 0.1;       // as TrackerOptions::cost_tolerance (0: only the least Γ)

  // Throws std::invalid_argument naming a bad value: previous_area not finite and > 0,
  // min_similarity outside [0, 1], tolerance negative or not finite.
  void check() const;
  // The largest admissible area, A_p / min_similarity (infinity for min_similarity 0).
  double max_area() const;

  void start() override;
  double gap_limit() const override;
  bool keep(const CandidateSummary& candidate) override;

 private:
  double best_cost_ = std::numeric_limits<double>::infinity();
};

}  // namespace scbt
