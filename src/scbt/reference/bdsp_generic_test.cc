// The generic-graph baseline (Boost.Graph) against the fast search.
#include "scbt/reference/bdsp_generic.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "scbt/cycles/bdsp.h"
#include "scbt/graph/segment_graph.h"
#include "scbt/reference/generic_cycle_stage.h"
#include "scbt/testing/random_graphs.h"

namespace scbt {
namespace {

// Least Γ = gap / area among candidates whose area is within `min_similarity` of `area`
// (infinity when none is).
double least_admissible_cost(const std::vector<CandidateSummary>& candidates, double area,
                             double min_similarity) {
  double best = std::numeric_limits<double>::infinity();
  for (const CandidateSummary& c : candidates) {
    if (!(c.area > 0.0) || std::min(c.area / area, area / c.area) <= min_similarity) continue;
    best = std::min(best, c.gap_length / c.area);
  }
  return best;
}

std::vector<CandidateSummary> summaries(const std::vector<CycleCandidate>& candidates) {
  std::vector<CandidateSummary> out;
  for (const CycleCandidate& c : candidates) out.push_back({c.gap_length, c.area, c.seed_edge});
  return out;
}

// Segments that share no endpoint: every tie in path length is between the two ends of one
// zero-weight segment, which never makes two shortest paths, so both searches must agree.
class BdspGenericTieFree : public ::testing::TestWithParam<unsigned> {};

TEST_P(BdspGenericTieFree, SameCandidatesAsCycleSearch) {
  std::mt19937 rng(GetParam() * 2654435761u + 17u);
  const int count = std::uniform_int_distribution<int>(3, 80)(rng);
  const SegmentGraph graph = build_segment_graph(random_segments(rng, count, false));
  BdspOptions options;
  options.seed_stride = std::uniform_int_distribution<int>(1, 3)(rng);
  const std::vector<CycleCandidate> generic = search_cycle_candidates_generic(graph, options);
  CycleSearch search;
  search.run(graph, options);
  ASSERT_EQ(generic.size(), search.candidates().size());
  std::vector<int> cycle;
  for (size_t k = 0; k < generic.size(); ++k) {
    const CandidateSummary& fast = search.candidates()[k];
    EXPECT_EQ(generic[k].seed_edge, fast.seed_edge) << k;
    EXPECT_NEAR(generic[k].gap_length, fast.gap_length, 1e-12 * (1.0 + fast.gap_length)) << k;
    EXPECT_NEAR(generic[k].area, fast.area, 1e-9 * (1.0 + fast.area)) << k;
    search.vertices(static_cast<int>(k), &cycle);
    EXPECT_EQ(generic[k].vertices, cycle) << k;
  }
}

INSTANTIATE_TEST_SUITE_P(Seeds, BdspGenericTieFree, ::testing::Range(0u, 60u));

// Shared endpoints: whatever parents the two searches pick among equal paths, the least cost
// of a candidate whose area is near a reference area is the same.
class BdspGenericAnyGraph : public ::testing::TestWithParam<unsigned> {};

TEST_P(BdspGenericAnyGraph, SameLeastAdmissibleCost) {
  std::mt19937 rng(GetParam() * 40503u + 5u);
  const int count = std::uniform_int_distribution<int>(3, 80)(rng);
  const SegmentGraph graph = build_segment_graph(random_segments(rng, count, true));
  BdspOptions options;
  options.seed_stride = std::uniform_int_distribution<int>(1, 3)(rng);
  const std::vector<CandidateSummary> generic =
      summaries(search_cycle_candidates_generic(graph, options));
  CycleSearch search;
  search.run(graph, options);
  ASSERT_EQ(generic.size(), search.candidates().size());
  // Reference areas: those of the candidates themselves and a spread around them.
  std::uniform_real_distribution<double> scale(0.5, 2.0);
  for (size_t k = 0; k < generic.size(); ++k) {
    for (const double area : {generic[k].area, generic[k].area * scale(rng)}) {
      if (!(area > 0.0)) continue;
      const double expected = least_admissible_cost(generic, area, 0.8);
      const double got = least_admissible_cost(search.candidates(), area, 0.8);
      if (std::isinf(expected)) {
        EXPECT_TRUE(std::isinf(got)) << k;
      } else {
        EXPECT_NEAR(got, expected, 1e-9 * expected) << k << " area " << area;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Seeds, BdspGenericAnyGraph, ::testing::Range(0u, 60u));

// The straightforward stages 5-6 of `scbt bench` choose a cycle of the same least cost as the
// tracker's (the cost does not depend on how shortest-path ties are broken).
TEST(GenericCycleStage, ChoosesTheLeastCostLikeTheFastStage) {
  int compared = 0;
  for (unsigned seed = 0; seed < 20; ++seed) {
    std::mt19937 rng(seed);
    const SegmentGraph graph = build_segment_graph(random_segments(rng, 40, true));
    FastCycleStage fast;
    GenericCycleStage generic;
    fast.search(graph, {});
    generic.search(graph, {});
    ASSERT_EQ(fast.num_candidates() > 0, generic.num_candidates() > 0) << seed;
    if (fast.num_candidates() == 0) continue;
    // Previous boundary: the fast stage's first candidate; a loose gate admits many.
    const Polygon previous = fast.polygon(graph, 0);
    StableChooser fast_chooser, generic_chooser;
    const auto a = fast.choose(&fast_chooser, graph, previous, 0.5, 0.0, nullptr);
    const auto b = generic.choose(&generic_chooser, graph, previous, 0.5, 0.0, nullptr);
    ASSERT_TRUE(a.has_value()) << seed;
    ASSERT_TRUE(b.has_value()) << seed;
    EXPECT_NEAR(a->cost, b->cost, 1e-9 * (1.0 + a->cost)) << seed;
    EXPECT_NEAR(generic.area(b->index), area(generic.polygon(graph, b->index)),
                1e-6 * generic.area(b->index))
        << seed;
    ++compared;
  }
  EXPECT_GT(compared, 10);
}

TEST(BdspGeneric, RejectsBadStride) {
  BdspOptions options;
  options.seed_stride = 0;
  const SegmentGraph graph = build_segment_graph({{{0, 0}, {10, 0}}});
  EXPECT_THROW(search_cycle_candidates_generic(graph, options), std::invalid_argument);
}

}  // namespace
}  // namespace scbt
