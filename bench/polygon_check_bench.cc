// Validation of an initial boundary (check_boundary_polygon, whose is_simple sweeps the edges)
// on a circle, its typical case, and on a comb, the worst case: every edge spans the same x
// range, so the sweep meets n^2 / 2 pairs. Sizes up to kMaxBoundaryVertices.
#include <benchmark/benchmark.h>

#include <cmath>

#include "scbt/geometry/polygon_io.h"

namespace {

scbt::Polygon circle(int n) {
  scbt::Polygon polygon;
  for (int i = 0; i < n; ++i) {
    const double angle = 2.0 * M_PI * i / n;
    polygon.emplace_back(5000 + 4000 * std::cos(angle), 5000 + 4000 * std::sin(angle));
  }
  return polygon;
}

// A zigzag between x = 0 and x = 1000 climbing 1 unit per edge, closed by a wall at x = -1.
scbt::Polygon comb(int n) {
  scbt::Polygon polygon;
  for (int i = 0; i < n - 2; ++i) polygon.emplace_back(i % 2 == 0 ? 0.0 : 1000.0, i);
  polygon.emplace_back(-1.0, n - 3);
  polygon.emplace_back(-1.0, 0.0);
  return polygon;
}

void BM_CheckCircle(benchmark::State& state) {
  const scbt::Polygon polygon = circle(static_cast<int>(state.range(0)));
  for (auto _ : state) scbt::check_boundary_polygon(polygon);
}
BENCHMARK(BM_CheckCircle)
    ->Arg(100)
    ->Arg(1000)
    ->Arg(scbt::kMaxBoundaryVertices)
    ->Unit(benchmark::kMillisecond);

void BM_CheckComb(benchmark::State& state) {
  const scbt::Polygon polygon = comb(static_cast<int>(state.range(0)));
  for (auto _ : state) scbt::check_boundary_polygon(polygon);
}
BENCHMARK(BM_CheckComb)
    ->Arg(100)
    ->Arg(1000)
    ->Arg(scbt::kMaxBoundaryVertices)
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
