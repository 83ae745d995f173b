// Stages 5-6 of one tracking attempt behind one interface: the cycle candidates of the segment
// graph and the one chosen. The tracker runs CycleSearch (FastCycleStage); `scbt bench` swaps in
// the straightforward implementation of reference/ to measure against.
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
  // Stage 6: the candidate chosen by `chooser` (Eq. 1-2, stabilised); std::nullopt if none is
  // admissible.
  virtual std::optional<BoundaryChoice> choose(StableChooser* chooser, const SegmentGraph& graph,
                                               const Polygon& previous, double min_similarity,
                                               double tolerance,
                                               const KnownSegmentDistances* known) = 0;
  virtual int num_candidates() const = 0;
  virtual Polygon polygon(const SegmentGraph& graph, int index) const = 0;
  virtual double area(int index) const = 0;
};

// The tracker's own: CycleSearch, candidates listed only when the choice asks.
class FastCycleStage : public CycleStage {
 public:
  void search(const SegmentGraph& graph, const BdspOptions& options) override;
  std::optional<BoundaryChoice> choose(StableChooser* chooser, const SegmentGraph& graph,
                                       const Polygon& previous, double min_similarity,
                                       double tolerance,
                                       const KnownSegmentDistances* known) override;
  int num_candidates() const override { return search_.size(); }
  Polygon polygon(const SegmentGraph& graph, int index) const override;
  double area(int index) const override { return search_.candidates()[index].area; }

 private:
  CycleSearch search_;
};

}  // namespace scbt
