// Stage 5 the straightforward way, for `scbt bench`'s baseline configuration: BDSP on Boost.Graph
// (bdsp_generic.h) with every candidate materialised; the choice is CycleStage's, as the tracker's.
#pragma once

#include <vector>

#include "scbt/tracker/cycle_stage.h"

namespace scbt {

class GenericCycleStage : public CycleStage {
 public:
  void search(const SegmentGraph& graph, const BdspOptions& options) override;
  const std::vector<CandidateSummary>& summaries() const override { return summaries_; }
  void vertices(int index, std::vector<int>* cycle) const override {
    *cycle = candidates_[index].vertices;
  }

 private:
  std::vector<CycleCandidate> candidates_;
  std::vector<CandidateSummary> summaries_;
};

}  // namespace scbt
