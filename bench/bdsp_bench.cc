// BDSP cycle-candidate search (stage 5) at the dataset's scale, three ways: CycleSearch (the
// tracker's path: summaries, vertices on demand), search_cycle_candidates (every candidate
// materialised, on top of CycleSearch) and the generic-graph baseline (Boost.Graph Dijkstra,
// every candidate materialised). Inputs as in stage_bench.cc: 50-150 segments, two thirds of
// them broken pieces of an elliptic boundary, the rest distractors near it. Run pinned:
//   taskset -c 0 build/bench/scbt_bdsp_bench
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "bench_inputs.h"
#include "scbt/cycles/bdsp.h"
#include "scbt/graph/segment_graph.h"
#include "scbt/reference/bdsp_generic.h"
#include "scbt/reference/candidate_gate.h"

namespace scbt {
namespace {

using bench_inputs::make_boundary;
using bench_inputs::make_segments;

SegmentGraph make_graph(const benchmark::State& state) {
  return build_segment_graph(make_segments(make_boundary(), static_cast<int>(state.range(0)), 13));
}

void set_counters(benchmark::State& state, const SegmentGraph& graph, size_t candidates) {
  state.counters["candidates"] = static_cast<double>(candidates);
  state.counters["vertices"] = graph.num_vertices();
  state.counters["edges"] = graph.num_edges();
}

void BM_CycleSearch(benchmark::State& state) {
  const SegmentGraph graph = make_graph(state);
  CycleSearch search;
  for (auto _ : state) {
    search.run(graph);
    benchmark::DoNotOptimize(search.candidates().data());
  }
  set_counters(state, graph, search.candidates().size());
}
BENCHMARK(BM_CycleSearch)->Arg(50)->Arg(100)->Arg(150)->Unit(benchmark::kMicrosecond);

// The tracker's path with the choice's gate (previous area = the ellipse's, similarity 0.9,
// tolerance 0.1): bounded searches, only candidates that can be near ties kept.
void BM_CycleSearchGated(benchmark::State& state) {
  const SegmentGraph graph = make_graph(state);
  CycleSearch search;
  CandidateGate gate;
  gate.previous_area = area(make_boundary());
  for (auto _ : state) {
    search.run(graph, BdspOptions{}, &gate);
    benchmark::DoNotOptimize(search.candidates().data());
  }
  set_counters(state, graph, search.candidates().size());
  double bounded = 0.0;
  for (double limit : search.seed_limits()) bounded += std::isfinite(limit) ? limit : 0.0;
  state.counters["mean_limit"] = bounded / std::max<size_t>(1, search.seed_limits().size());
}
BENCHMARK(BM_CycleSearchGated)->Arg(50)->Arg(100)->Arg(150)->Unit(benchmark::kMicrosecond);

void BM_SearchCycleCandidates(benchmark::State& state) {
  const SegmentGraph graph = make_graph(state);
  size_t candidates = 0;
  for (auto _ : state) {
    const std::vector<CycleCandidate> found = search_cycle_candidates(graph);
    candidates = found.size();
    benchmark::DoNotOptimize(found.data());
  }
  set_counters(state, graph, candidates);
}
BENCHMARK(BM_SearchCycleCandidates)->Arg(50)->Arg(100)->Arg(150)->Unit(benchmark::kMicrosecond);

void BM_GenericGraph(benchmark::State& state) {
  const SegmentGraph graph = make_graph(state);
  size_t candidates = 0;
  for (auto _ : state) {
    const std::vector<CycleCandidate> found = search_cycle_candidates_generic(graph);
    candidates = found.size();
    benchmark::DoNotOptimize(found.data());
  }
  set_counters(state, graph, candidates);
}
BENCHMARK(BM_GenericGraph)->Arg(50)->Arg(100)->Arg(150)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace scbt

BENCHMARK_MAIN();
