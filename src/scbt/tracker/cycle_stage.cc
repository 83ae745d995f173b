#include "scbt/tracker/cycle_stage.h"

namespace scbt {

void FastCycleStage::search(const SegmentGraph& graph, const BdspOptions& options) {
  search_.run(graph, options);
}

std::optional<BoundaryChoice> FastCycleStage::choose(StableChooser* chooser,
                                                     const SegmentGraph& graph,
                                                     const Polygon& previous, double min_similarity,
                                                     double tolerance,
                                                     const KnownSegmentDistances* known) {
  return chooser->choose(
      search_.candidates(),
      [&](int index, std::vector<int>* cycle) { search_.vertices(index, cycle); }, graph, previous,
      min_similarity, tolerance, known);
}

Polygon FastCycleStage::polygon(const SegmentGraph& graph, int index) const {
  thread_local std::vector<int> cycle;
  search_.vertices(index, &cycle);
  Polygon polygon;
  polygon.reserve(cycle.size());
  for (int v : cycle) polygon.push_back(graph.vertices[v]);
  return polygon;
}

}  // namespace scbt
