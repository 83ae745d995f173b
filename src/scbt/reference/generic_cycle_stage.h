// Stages 5-6 the straightforward way, for `scbt bench`'s baseline configuration: BDSP on
// Boost.Graph (bdsp_generic.h) with every candidate materialised, then the same choice.
#pragma once

#include <vector>

#include "scbt/tracker/cycle_stage.h"

namespace scbt {

class GenericCycleStage : public CycleStage {
 public:
  void search(const SegmentGraph& graph, const BdspOptions& options) override;
  std::optional<BoundaryChoice> choose(StableChooser* chooser, const SegmentGraph& graph,
                                       const Polygon& previous, double min_similarity,
                                       double tolerance,
                                       const KnownSegmentDistances* known) override;
  int num_candidates() const override { return static_cast<int>(candidates_.size()); }
  Polygon polygon(const SegmentGraph& graph, int index) const override;
  double area(int index) const override { return candidates_[index].area; }

 private:
  std::vector<CycleCandidate> candidates_;
};

}  // namespace scbt
