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

#include "scbt/grouping/bdsp.h"
#include "scbt/grouping/bdsp_generic.h"
#include "scbt/grouping/segment_graph.h"

namespace scbt {
namespace {

Polygon make_boundary() {
  Polygon boundary;
  for (int k = 0; k < 16; ++k) {
    const double t = 2.0 * M_PI * k / 16.0;
    boundary.push_back({320.0 + 150.0 * std::cos(t), 240.0 + 100.0 * std::sin(t)});
  }
  return boundary;
}

std::vector<Segment> make_segments(const Polygon& boundary, int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0), jitter(-1.0, 1.0), offset(-15.0, 15.0);
  std::vector<Segment> segments;
  const int n = static_cast<int>(boundary.size());
  const int on_boundary = count * 2 / 3;
  const int pieces = std::max(1, on_boundary / n);
  for (int i = 0; i < n; ++i) {
    const Point a = boundary[i], b = boundary[(i + 1) % n];
    for (int k = 0; k < pieces; ++k) {
      const double t0 = (k + 0.1 * unit(rng)) / pieces, t1 = (k + 0.8 + 0.1 * unit(rng)) / pieces;
      segments.push_back({a + (b - a) * t0 + Point(jitter(rng), jitter(rng)),
                          a + (b - a) * t1 + Point(jitter(rng), jitter(rng))});
    }
  }
  while (static_cast<int>(segments.size()) < count) {
    const Point p = boundary[static_cast<int>(unit(rng) * n) % n] + Point(offset(rng), offset(rng));
    const double angle = 2.0 * M_PI * unit(rng), length = 8.0 + 30.0 * unit(rng);
    segments.push_back({p, p + Point(std::cos(angle), std::sin(angle)) * length});
  }
  return segments;
}

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
