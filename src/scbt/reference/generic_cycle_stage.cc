#include "scbt/reference/generic_cycle_stage.h"

#include "scbt/reference/bdsp_generic.h"

namespace scbt {

void GenericCycleStage::search(const SegmentGraph& graph, const BdspOptions& options) {
  candidates_ = search_cycle_candidates_generic(graph, options);
}

std::optional<BoundaryChoice> GenericCycleStage::choose(StableChooser* chooser,
                                                        const SegmentGraph& graph,
                                                        const Polygon& previous,
                                                        double min_similarity, double tolerance,
                                                        const KnownSegmentDistances* known) {
  return chooser->choose(
      candidates_,
      [&](int index, std::vector<int>* cycle) { *cycle = candidates_[index].vertices; }, graph,
      previous, min_similarity, tolerance, known);
}

Polygon GenericCycleStage::polygon(const SegmentGraph& graph, int index) const {
  return candidate_polygon(graph, candidates_[index]);
}

}  // namespace scbt
