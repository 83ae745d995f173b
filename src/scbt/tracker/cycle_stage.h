// Stages 5-6 of one tracking attempt behind one interface: the cycle candidates of the segment
// graph and the one chosen. The tracker runs CycleSearch (FastCycleStage); `scbt bench` swaps in
// the straightforward implementation of reference/ to measure against. A stage only searches and
// lists; the choice (Eq. 1-2, stabilised) is the same code for every stage.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "scbt/choice/boundary_choice.h"
#include "scbt/cycles/bdsp.h"
#include "scbt/geometry/polygon.h"
#include "scbt/graph/segment_graph.h"

namespace scbt {

class CycleStage {
 public:
  virtual ~CycleStage() = default;
  // Stage 5: the candidates of `graph` (kept until the next search).
  virtual void search(const SegmentGraph& graph, const BdspOptions& options) = 0;
  // Gap and area of every candidate of the last search.
  virtual const std::vector<CandidateSummary>& summaries() const = 0;
  // The graph vertices of candidate `index`, in cycle order.
  virtual void vertices(int index, std::vector<int>* cycle) const = 0;

  // Stage 6: the candidate chosen by `chooser`; std::nullopt if none is admissible.
  std::optional<BoundaryChoice> choose(StableChooser* chooser, const SegmentGraph& graph,
                                       const Polygon& previous, double min_similarity,
                                       double tolerance, const KnownSegmentDistances* known,
                                       double gate_area = 0.0,
                                       const RankingWeights& weights = {}) const;
  int num_candidates() const { return static_cast<int>(summaries().size()); }
  Polygon polygon(const SegmentGraph& graph, int index) const;
  double area(int index) const { return summaries()[index].area; }
};

// The tracker's own: CycleSearch, candidates listed only when the choice asks.
class FastCycleStage : public CycleStage {
 public:
  void search(const SegmentGraph& graph, const BdspOptions& options) override {
    search_.run(graph, options);
  }
  const std::vector<CandidateSummary>& summaries() const override { return search_.candidates(); }
  void vertices(int index, std::vector<int>* cycle) const override {
    search_.vertices(index, cycle);
  }

 private:
  CycleSearch search_;
};

}  // namespace scbt
