#include "scbt/reference/generic_cycle_stage.h"

#include "scbt/reference/bdsp_generic.h"

namespace scbt {

void GenericCycleStage::search(const SegmentGraph& graph, const BdspOptions& options) {
  candidates_ = search_cycle_candidates_generic(graph, options);
  summaries_.clear();
  for (const CycleCandidate& c : candidates_)
    summaries_.push_back({c.gap_length, c.area, c.seed_edge});
}

}  // namespace scbt
