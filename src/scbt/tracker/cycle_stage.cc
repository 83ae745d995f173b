#include "scbt/tracker/cycle_stage.h"

namespace scbt {

std::optional<BoundaryChoice> CycleStage::choose(StableChooser* chooser, const SegmentGraph& graph,
                                                 const Polygon& previous, double min_similarity,
                                                 double tolerance,
                                                 const KnownSegmentDistances* known,
                                                 double gate_area,
                                                 const RankingWeights& weights) const {
  return chooser->choose(
      summaries(), [this](int index, std::vector<int>* cycle) { vertices(index, cycle); }, graph,
      previous, min_similarity, tolerance, known, gate_area, weights);
}

Polygon CycleStage::polygon(const SegmentGraph& graph, int index) const {
  thread_local std::vector<int> cycle;
  vertices(index, &cycle);
  Polygon polygon;
  polygon.reserve(cycle.size());
  for (int v : cycle) polygon.push_back(graph.vertices[v]);
  return polygon;
}

}  // namespace scbt
