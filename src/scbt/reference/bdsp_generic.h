// The generic-graph baseline of stage 5: BDSP written straightforwardly on Boost.Graph.
#pragma once

#include <vector>

#include "scbt/cycles/bdsp.h"
#include "scbt/graph/segment_graph.h"

namespace scbt {

// The same search as search_cycle_candidates (same seeds, third vertices, meeting rule, repeat
// and size filters), written the straightforward way: the graph is copied into a
// boost::adjacency_list for every call, each seed's two searches are
// boost::dijkstra_shortest_paths on a filtered_graph that hides the seed edge, and every
// candidate's cycle is materialised and its area computed by walking it. Where shortest paths
// tie, Boost may pick other parents, so the candidates can differ; the least cost does not.
// The "generic graph" configuration the fast search is measured against (in
// `scbt bench`, through GenericCycleStage); not for production use.
std::vector<CycleCandidate> search_cycle_candidates_generic(const SegmentGraph& graph,
                                                            const BdspOptions& options = {});

}  // namespace scbt
