// A Tracker assembled with other stages 5-6 than its own (FastCycleStage): how `scbt bench`
// measures the straightforward pipeline from reference/ against it. Internal, not installed.
#pragma once

#include <functional>
#include <memory>

#include "scbt/tracker/cycle_stage.h"
#include "scbt/tracker/tracker.h"
#include "scbt/tracker/tracker_options.h"

namespace scbt {

// Builds the cycle stage (stages 5-6) of each of the tracker's searches.
using MakeCycleStage = std::function<std::unique_ptr<CycleStage>()>;

// A tracker whose stages 5-6 are the ones `make_cycle_stage` makes. Throws like Tracker().
Tracker make_tracker(const TrackerOptions& options, const MakeCycleStage& make_cycle_stage);

}  // namespace scbt
