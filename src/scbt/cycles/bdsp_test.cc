// BDSP cycle candidates: structural properties on random graphs, and recovery of a known cycle.
#include "scbt/cycles/bdsp.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "scbt/choice/boundary_choice.h"
#include "scbt/graph/segment_graph.h"
#include "scbt/reference/bdsp_generic.h"
#include "scbt/reference/candidate_gate.h"
#include "scbt/reference/shortest_paths.h"
#include "scbt/testing/random_graphs.h"

namespace scbt {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Edge index by unordered vertex pair.
std::map<std::pair<int, int>, int> edge_index(const SegmentGraph& graph) {
  std::map<std::pair<int, int>, int> index;
  for (int i = 0; i < graph.num_edges(); ++i) {
    const GraphEdge& e = graph.edges[i];
    index[{std::min(e.u, e.v), std::max(e.u, e.v)}] = i;
  }
  return index;
}

double shoelace(const Polygon& p) {
  double twice = 0.0;
  for (size_t i = 0; i < p.size(); ++i) {
    const Point& a = p[i];
    const Point& b = p[(i + 1) % p.size()];
    twice += a.x * b.y - b.x * a.y;
  }
  return 0.5 * twice;
}

// The straightforward BDSP of the paper, kept here as the reference the optimised search must
// match candidate for candidate: mark the whole second path for every third vertex, walk the
// first path from s1 to the first marked vertex.
// With `limits` (one per seed), a seed's third vertices farther than its limit from s1 or s2
// are left out, as CandidateGate's bounded searches do.
std::vector<CycleCandidate> reference_candidates(const SegmentGraph& graph, int stride,
                                                 const std::vector<double>* limits = nullptr,
                                                 std::vector<int>* meetings = nullptr) {
  std::vector<CycleCandidate> candidates;
  const int n = graph.num_vertices();
  ShortestPaths first, second;
  std::vector<int> seen(n, -1);
  const int num_detected = static_cast<int>(graph.detected_edges.size());
  for (int i = 0; i < num_detected; i += stride) {
    const int seed = graph.detected_edges[i];
    const int s1 = graph.edges[seed].u, s2 = graph.edges[seed].v;
    first.run(graph, s1, seed);
    second.run(graph, s2, seed);
    for (int j = 0; j < num_detected; ++j) {
      const int third = graph.edges[graph.detected_edges[j]].u;
      if (j == i || !first.reached(third) || !second.reached(third)) continue;
      if (limits != nullptr && (first.distance(third) > (*limits)[i / stride] ||
                                second.distance(third) > (*limits)[i / stride])) {
        continue;
      }
      std::set<int> on_second;
      for (int v = third; v != -1; v = second.parent_vertex(v)) on_second.insert(v);
      std::vector<int> path;
      for (int v = third; v != -1; v = first.parent_vertex(v)) path.push_back(v);
      std::reverse(path.begin(), path.end());
      size_t meet = 0;
      while (!on_second.count(path[meet])) ++meet;
      if (seen[path[meet]] == i) continue;
      seen[path[meet]] = i;
      CycleCandidate c;
      c.seed_edge = seed;
      c.vertices.assign(path.begin(), path.begin() + meet + 1);
      for (int v = path[meet]; v != s2; v = second.parent_vertex(v)) {
        c.vertices.push_back(second.parent_vertex(v));
      }
      if (c.vertices.size() < 3) continue;
      c.gap_length = first.distance(path[meet]) + second.distance(path[meet]);
      Polygon polygon;
      for (int v : c.vertices) polygon.push_back(graph.vertices[v]);
      c.area = std::abs(shoelace(polygon));
      candidates.push_back(c);
      if (meetings != nullptr) meetings->push_back(path[meet]);
    }
  }
  return candidates;
}

// Where path lengths tie, CycleSearch (which searches over contracted segments) may pick other
// shortest paths than the reference, so other candidates. What holds for every candidate k
// whatever the ties: its cycle visits each vertex once and is closed by its seed edge; the part
// from s1 to its meeting vertex and the part from the meeting vertex back to s2 are shortest
// paths (their weights summed in path order equal the reference Dijkstra's distances bit for
// bit), and the gap is the sum of the two; the area is the cycle's shoelace area; a seed lists
// each meeting vertex once. Returns the number of candidates checked.
int expect_shortest_path_cycles(const SegmentGraph& graph, int stride, const CycleSearch& search) {
  ShortestPaths from_s1, from_s2;
  std::vector<int> cycle;
  std::set<std::pair<int, int>> meetings;  // (seed edge, meeting vertex)
  int last_seed = -1;
  for (int k = 0; k < search.size(); ++k) {
    SCOPED_TRACE("candidate " + std::to_string(k));
    const CandidateSummary& c = search.candidates()[k];
    const int slot = static_cast<int>(
        std::find(graph.detected_edges.begin(), graph.detected_edges.end(), c.seed_edge) -
        graph.detected_edges.begin());
    EXPECT_EQ(slot % stride, 0) << "not a seed";
    const int s1 = graph.edges[c.seed_edge].u, s2 = graph.edges[c.seed_edge].v;
    if (c.seed_edge != last_seed) {
      from_s1.run(graph, s1, c.seed_edge);
      from_s2.run(graph, s2, c.seed_edge);
      last_seed = c.seed_edge;
    }
    search.vertices(k, &cycle);
    EXPECT_GE(cycle.size(), 3u);
    EXPECT_EQ(std::set<int>(cycle.begin(), cycle.end()).size(), cycle.size()) << "a vertex repeats";
    EXPECT_EQ(cycle.front(), s1);
    EXPECT_EQ(cycle.back(), s2);
    const int meeting = search.meeting(k);
    EXPECT_TRUE(meetings.insert({c.seed_edge, meeting}).second) << "meeting listed twice";
    const auto at = std::find(cycle.begin(), cycle.end(), meeting);
    EXPECT_NE(at, cycle.end()) << "meeting not on the cycle";
    if (at == cycle.end()) continue;
    // Path weights, summed from each root in path order, with the lightest edge between two
    // consecutive vertices other than the seed edge.
    const auto hop = [&](int a, int b) {
      double best = HUGE_VAL;
      for (int e = 0; e < graph.num_edges(); ++e) {
        const GraphEdge& edge = graph.edges[e];
        if (e != c.seed_edge && ((edge.u == a && edge.v == b) || (edge.u == b && edge.v == a))) {
          best = std::min(best, edge.weight);
        }
      }
      return best;
    };
    const size_t m = static_cast<size_t>(at - cycle.begin());
    double first = 0.0, second = 0.0;
    for (size_t i = 0; i < m; ++i) first += hop(cycle[i], cycle[i + 1]);
    for (size_t i = cycle.size() - 1; i > m; --i) second += hop(cycle[i], cycle[i - 1]);
    EXPECT_EQ(first, from_s1.distance(meeting));
    EXPECT_EQ(second, from_s2.distance(meeting));
    EXPECT_EQ(c.gap_length, from_s1.distance(meeting) + from_s2.distance(meeting));
    Polygon polygon;
    for (int v : cycle) polygon.push_back(graph.vertices[v]);
    EXPECT_NEAR(c.area, std::abs(shoelace(polygon)), 1e-9 * (1.0 + c.area));
  }
  return search.size();
}

class BdspMatchesReference : public ::testing::TestWithParam<unsigned> {};

TEST_P(BdspMatchesReference, SameCandidatesInSameOrder) {
  std::mt19937 rng(GetParam() * 7919u + 3u);
  std::uniform_int_distribution<int> count(3, 120), stride(1, 3);
  const SegmentGraph graph = build_segment_graph(random_segments(rng, count(rng), true));
  BdspOptions options;
  options.seed_stride = stride(rng);
  const std::vector<CycleCandidate> expected = reference_candidates(graph, options.seed_stride);
  // Twice: the second call runs on buffers left over from the first.
  for (int round = 0; round < 2; ++round) {
    const std::vector<CycleCandidate> got = search_cycle_candidates(graph, options);
    ASSERT_EQ(got.size(), expected.size()) << "round " << round;
    for (size_t k = 0; k < got.size(); ++k) {
      EXPECT_EQ(got[k].vertices, expected[k].vertices) << k;
      EXPECT_EQ(got[k].seed_edge, expected[k].seed_edge) << k;
      EXPECT_EQ(got[k].gap_length, expected[k].gap_length) << k;
      EXPECT_NEAR(got[k].area, expected[k].area, 1e-6 * (1.0 + expected[k].area)) << k;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Seeds, BdspMatchesReference, ::testing::Range(0u, 60u));

// Segments with endpoints on a coarse integer grid: many equal path lengths (ties) and shared
// endpoints (zero-weight paths of several segments).
std::vector<Segment> grid_segments(std::mt19937& rng, int count) {
  std::uniform_int_distribution<int> pos(0, 12), step(-3, 3);
  std::vector<Segment> segments;
  for (int attempt = 0; static_cast<int>(segments.size()) < count && attempt < 50 * count;
       ++attempt) {
    const Point a(10.0 * pos(rng), 10.0 * pos(rng));
    const Segment s{a, a + Point(10.0 * step(rng), 10.0 * step(rng))};
    if (std::none_of(segments.begin(), segments.end(),
                     [&](const Segment& other) { return properly_cross(s, other); })) {
      segments.push_back(s);
    }
  }
  return segments;
}

// One CycleSearch reused over graphs of changing size: on random segments (ties have probability
// ~0) summaries and the vertices listed on demand are the reference's, candidate for candidate;
// on grid segments (ties everywhere) the candidates are shortest-path cycles.
TEST(CycleSearch, MatchesReferenceOnReusedBuffers) {
  CycleSearch search;
  std::vector<int> cycle;
  int tied_candidates = 0;
  for (unsigned trial = 0; trial < 120; ++trial) {
    std::mt19937 rng(trial * 31u + 1u);
    const int count = std::uniform_int_distribution<int>(3, 100)(rng);
    const bool grid = trial % 2 == 0;
    const SegmentGraph graph =
        build_segment_graph(grid ? grid_segments(rng, count) : random_segments(rng, count, true));
    BdspOptions options;
    options.seed_stride = std::uniform_int_distribution<int>(1, 3)(rng);
    search.run(graph, options);
    SCOPED_TRACE("trial " + std::to_string(trial));
    if (grid) {
      tied_candidates += expect_shortest_path_cycles(graph, options.seed_stride, search);
      continue;
    }
    const std::vector<CycleCandidate> expected = reference_candidates(graph, options.seed_stride);
    ASSERT_EQ(search.size(), static_cast<int>(expected.size()));
    for (int k = 0; k < search.size(); ++k) {
      const CandidateSummary& got = search.candidates()[k];
      EXPECT_EQ(got.seed_edge, expected[k].seed_edge) << k;
      EXPECT_EQ(got.gap_length, expected[k].gap_length) << k;
      EXPECT_NEAR(got.area, expected[k].area, 1e-9 * (1.0 + expected[k].area)) << k;
      search.vertices(k, &cycle);
      EXPECT_EQ(cycle, expected[k].vertices) << k;
    }
  }
  EXPECT_GT(tied_candidates, 1000);
}

// Random multigraphs whose weights are decimal fractions (0.1 + 0.2 != 0.3 in doubles): path
// lengths that tie in exact arithmetic may or may not tie once rounded, differently from each
// root, which is where the two trees can part and meet again.
SegmentGraph rounding_graph(std::mt19937& rng, int n, int m) {
  return random_multigraph(
      rng, n, m, [](std::mt19937& r) { return 0.1 * std::uniform_int_distribution<int>(1, 7)(r); });
}

TEST(CycleSearch, ShortestPathCyclesWithRoundedTies) {
  CycleSearch search;
  int checked = 0;
  for (unsigned trial = 0; trial < 400; ++trial) {
    std::mt19937 rng(trial * 977u + 3u);
    const int n = std::uniform_int_distribution<int>(3, 40)(rng);
    const SegmentGraph graph =
        rounding_graph(rng, n, std::uniform_int_distribution<int>(n, 3 * n)(rng));
    BdspOptions options;
    options.seed_stride = std::uniform_int_distribution<int>(1, 2)(rng);
    search.run(graph, options);
    SCOPED_TRACE("trial " + std::to_string(trial));
    checked += expect_shortest_path_cycles(graph, options.seed_stride, search);
  }
  EXPECT_GT(checked, 1000);
}

TEST(CycleSearch, RejectsBadStrideAndIndex) {
  BdspOptions options;
  options.seed_stride = 0;
  EXPECT_THROW(options.check(), std::invalid_argument);
  CycleSearch search;
  EXPECT_THROW(search.run(build_segment_graph({{{0, 0}, {10, 0}}}), options),
               std::invalid_argument);
  search.run(build_segment_graph({{{0, 0}, {40, 0}}, {{40, 0}, {0, 30}}, {{0, 30}, {0, 0}}}));
  std::vector<int> cycle;
  EXPECT_THROW(search.vertices(search.size(), &cycle), std::out_of_range);
}

class BdspProperty : public ::testing::TestWithParam<unsigned> {};

TEST_P(BdspProperty, CandidatesAreSimpleCyclesClosedBySeed) {
  std::mt19937 rng(GetParam() * 101u + 11u);
  std::uniform_int_distribution<int> count(3, 30), stride(1, 3);
  const SegmentGraph graph = build_segment_graph(random_segments(rng, count(rng), true));
  BdspOptions options;
  options.seed_stride = stride(rng);
  const std::vector<CycleCandidate> candidates = search_cycle_candidates(graph, options);
  const auto index = edge_index(graph);
  ASSERT_FALSE(candidates.empty());

  std::set<int> allowed_seeds;
  for (size_t k = 0; k < graph.detected_edges.size(); k += options.seed_stride) {
    allowed_seeds.insert(graph.detected_edges[k]);
  }
  for (size_t c = 0; c < candidates.size(); ++c) {
    SCOPED_TRACE("candidate " + std::to_string(c));
    const CycleCandidate& candidate = candidates[c];
    const std::vector<int>& cycle = candidate.vertices;
    ASSERT_GE(cycle.size(), 3u);
    EXPECT_EQ(std::set<int>(cycle.begin(), cycle.end()).size(), cycle.size()) << "a vertex repeats";
    ASSERT_TRUE(allowed_seeds.count(candidate.seed_edge)) << "seed " << candidate.seed_edge;
    const GraphEdge& seed = graph.edges[candidate.seed_edge];
    EXPECT_TRUE(seed.detected);
    // The closing pair (last, first) is the seed edge.
    EXPECT_EQ(cycle.front(), seed.u);
    EXPECT_EQ(cycle.back(), seed.v);

    double gap = 0.0;
    for (size_t i = 0; i < cycle.size(); ++i) {
      const int u = cycle[i];
      const int v = cycle[(i + 1) % cycle.size()];
      ASSERT_GE(u, 0);
      ASSERT_LT(u, graph.num_vertices());
      const auto it = index.find({std::min(u, v), std::max(u, v)});
      ASSERT_NE(it, index.end()) << "no edge " << u << "-" << v;
      if (i + 1 == cycle.size()) {
        EXPECT_EQ(it->second, candidate.seed_edge);
      }
      if (!graph.edges[it->second].detected) gap += graph.edges[it->second].length;
    }
    EXPECT_NEAR(candidate.gap_length, gap, 1e-9 * (1.0 + gap));
    const Polygon polygon = candidate_polygon(graph, candidate);
    ASSERT_EQ(polygon.size(), cycle.size());
    for (size_t i = 0; i < cycle.size(); ++i) EXPECT_EQ(polygon[i], graph.vertices[cycle[i]]);
    EXPECT_NEAR(candidate.area, std::abs(shoelace(polygon)), 1e-9 * (1.0 + candidate.area));
  }
}

INSTANTIATE_TEST_SUITE_P(Seeds, BdspProperty, ::testing::Range(0u, 100u));

// A regular n-gon whose every side is two detected segments separated by small gaps (at the side
// middle and at each corner), surrounded by short distractor segments away from it.
struct BrokenPolygonScene {
  std::vector<Segment> segments;
  std::set<std::pair<double, double>> boundary_points;  // endpoints of the boundary segments
  Polygon outline;
};

BrokenPolygonScene broken_polygon(std::mt19937& rng, int sides) {
  std::uniform_real_distribution<double> radius(60.0, 150.0), rotation(-kPi, kPi),
      centre(200.0, 400.0), gap(1.0, 6.0), unit(0.0, 1.0), angle(-kPi, kPi);
  BrokenPolygonScene scene;
  const double r = radius(rng), phase = rotation(rng);
  const Point c(centre(rng), centre(rng));
  for (int i = 0; i < sides; ++i) {
    const double t = phase + 2.0 * kPi * i / sides;
    scene.outline.push_back(c + Point(std::cos(t), std::sin(t)) * r);
  }
  for (int i = 0; i < sides; ++i) {
    const Point a = scene.outline[i];
    const Point b = scene.outline[(i + 1) % sides];
    const double length = cv::norm(b - a);
    const Point dir = (b - a) * (1.0 / length);
    const double g0 = gap(rng) / 2, g1 = gap(rng) / 2, g2 = gap(rng) / 2;
    const double middle = length * (0.35 + 0.3 * unit(rng));
    const Segment first{a + dir * g0, a + dir * (middle - g1)};
    const Segment second{a + dir * (middle + g1), b - dir * g2};
    for (const Segment& s : {first, second}) {
      scene.segments.push_back(s);
      scene.boundary_points.emplace(s.a.x, s.a.y);
      scene.boundary_points.emplace(s.b.x, s.b.y);
    }
  }
  // Distractors: short segments at least 25 px from the outline, inside or outside it.
  std::uniform_real_distribution<double> pos(0.0, 600.0), len(3.0, 10.0);
  int added = 0;
  for (int attempt = 0; attempt < 2000 && added < 25; ++attempt) {
    const Point a(pos(rng), pos(rng));
    const double t = angle(rng);
    const Segment s{a, a + Point(std::cos(t), std::sin(t)) * len(rng)};
    if (distance_to_boundary(s.a, scene.outline) < 25.0 ||
        distance_to_boundary(s.b, scene.outline) < 25.0) {
      continue;
    }
    if (std::any_of(scene.segments.begin(), scene.segments.end(),
                    [&](const Segment& other) { return properly_cross(s, other); })) {
      continue;
    }
    scene.segments.push_back(s);
    ++added;
  }
  std::shuffle(scene.segments.begin(), scene.segments.end(), rng);
  return scene;
}

class BdspKnownCycle : public ::testing::TestWithParam<std::tuple<int, unsigned>> {};

TEST_P(BdspKnownCycle, ChooseBoundaryReturnsTheBrokenPolygon) {
  const auto [sides, seed] = GetParam();
  std::mt19937 rng(seed * 7u + static_cast<unsigned>(sides));
  const BrokenPolygonScene scene = broken_polygon(rng, sides);
  const SegmentGraph graph = build_segment_graph(scene.segments);
  const std::vector<CycleCandidate> candidates = search_cycle_candidates(graph, BdspOptions{});
  const std::optional<BoundaryChoice> choice =
      choose_boundary(candidates, area(scene.outline), 0.8);
  ASSERT_TRUE(choice.has_value());
  const CycleCandidate& chosen = candidates[choice->index];
  std::set<std::pair<double, double>> chosen_points;
  for (int v : chosen.vertices) chosen_points.emplace(graph.vertices[v].x, graph.vertices[v].y);
  EXPECT_EQ(chosen_points, scene.boundary_points);
  // Its gap is the sum of the small gaps between consecutive boundary segments.
  EXPECT_LT(chosen.gap_length, 6.0 * 2 * sides);
}

INSTANTIATE_TEST_SUITE_P(Shapes, BdspKnownCycle,
                         ::testing::Combine(::testing::Values(3, 4, 6, 8),
                                            ::testing::Range(0u, 15u)));

TEST(CandidateGate, RejectsBadValues) {
  CandidateGate gate;
  gate.previous_area = 100.0;
  EXPECT_NO_THROW(gate.check());
  const double nan = std::nan("");
  for (const double bad : {0.0, -1.0, nan, HUGE_VAL}) {
    CandidateGate g = gate;
    g.previous_area = bad;
    EXPECT_THROW(g.check(), std::invalid_argument) << bad;
  }
  for (const double bad : {-0.1, 1.1, nan}) {
    CandidateGate g = gate;
    g.min_similarity = bad;
    EXPECT_THROW(g.check(), std::invalid_argument) << bad;
  }
  for (const double bad : {-0.1, nan, HUGE_VAL}) {
    CandidateGate g = gate;
    g.tolerance = bad;
    EXPECT_THROW(g.check(), std::invalid_argument) << bad;
  }
  EXPECT_DOUBLE_EQ(gate.max_area(), 100.0 / 0.9);
  CandidateGate loose = gate;
  loose.min_similarity = 0.0;
  EXPECT_TRUE(std::isinf(loose.max_area()));
  CycleSearch search;
  CandidateGate bad = gate;
  bad.previous_area = -5.0;
  EXPECT_THROW(search.run(build_segment_graph({{{0, 0}, {10, 0}}}), BdspOptions{}, &bad),
               std::invalid_argument);
}

// A random graph of one of three kinds (random, grid, a broken polygon among distractors) and a
// gate around the area of one of its unbounded candidates (or of the polygon).
struct GatedCase {
  enum Kind { kRandom, kGrid, kPolygon };
  Kind kind = kRandom;
  SegmentGraph graph;
  BdspOptions options;
  CandidateGate gate;
  Polygon previous;
};

GatedCase gated_case(unsigned trial) {
  GatedCase c;
  std::mt19937 rng(trial * 613u + 29u);
  c.kind = static_cast<GatedCase::Kind>(trial % 3);
  const int count = std::uniform_int_distribution<int>(3, 100)(rng);
  if (c.kind == GatedCase::kPolygon) {
    const BrokenPolygonScene scene =
        broken_polygon(rng, std::uniform_int_distribution<int>(3, 8)(rng));
    c.graph = build_segment_graph(scene.segments);
    c.previous = scene.outline;
  } else {
    c.graph = build_segment_graph(c.kind == GatedCase::kRandom ? random_segments(rng, count, true)
                                                               : grid_segments(rng, count));
  }
  c.options.seed_stride = std::uniform_int_distribution<int>(1, 3)(rng);
  const double similarities[] = {0.0, 0.5, 0.8, 0.9, 0.9};
  const double tolerances[] = {0.0, 0.05, 0.1, 0.1, 0.5};
  c.gate.min_similarity = similarities[std::uniform_int_distribution<int>(0, 4)(rng)];
  c.gate.tolerance = tolerances[std::uniform_int_distribution<int>(0, 4)(rng)];
  return c;
}

// The previous boundary: the polygon scene's outline moved a little, or else a random unbounded
// candidate's cycle scaled a little about its centroid (so that some candidates are admissible).
Polygon previous_boundary(std::mt19937& rng, const GatedCase& c, const CycleSearch& unbounded) {
  std::uniform_real_distribution<double> scale(0.93, 1.07), shift(-4.0, 4.0);
  Polygon base = c.previous;
  if (base.empty()) {
    if (unbounded.size() == 0) return {{0, 0}, {10, 0}, {0, 10}};
    const CycleCandidate pick =
        unbounded.candidate(std::uniform_int_distribution<int>(0, unbounded.size() - 1)(rng));
    base = candidate_polygon(c.graph, pick);
  }
  Point centroid(0, 0);
  for (const Point& p : base) centroid += p * (1.0 / base.size());
  const double k = scale(rng);
  const Point move(shift(rng), shift(rng));
  Polygon previous;
  for (const Point& p : base) previous.push_back(centroid + (p - centroid) * k + move);
  return previous;
}

// The gated search is exactly the documented rule: per seed, the gap bound from the candidates
// kept before it, and the unbounded (reference) candidates whose third vertex is within that
// bound of both seed endpoints, filtered by admissibility and cost.
TEST(CandidateGate, KeepsExactlyTheDocumentedCandidates) {
  CycleSearch unbounded, gated;
  std::vector<int> cycle;
  int bounded_seeds = 0, lost_thirds = 0;
  for (unsigned trial = 0; trial < 240; ++trial) {
    GatedCase c = gated_case(trial);
    unbounded.run(c.graph, c.options);
    std::mt19937 rng(trial + 5u);
    const Polygon previous = previous_boundary(rng, c, unbounded);
    c.gate.previous_area = std::abs(shoelace(previous));
    if (!(c.gate.previous_area > 0.0)) continue;
    gated.run(c.graph, c.options, &c.gate);
    SCOPED_TRACE("trial " + std::to_string(trial));

    const int stride = c.options.seed_stride;
    const int num_seeds = (static_cast<int>(c.graph.detected_edges.size()) + stride - 1) / stride;
    const std::vector<double>& limits = gated.seed_limits();
    ASSERT_EQ(static_cast<int>(limits.size()), num_seeds);
    // The limits from the kept candidates.
    double best = HUGE_VAL;
    size_t k = 0;
    for (int slot = 0; slot < num_seeds; ++slot) {
      double expected = HUGE_VAL;
      if (best < HUGE_VAL) {
        expected =
            best > 0.0 ? (1.0 + c.gate.tolerance) * best * c.gate.max_area() * (1.0 + 1e-9) : 0.0;
      }
      EXPECT_EQ(limits[slot], expected) << "seed " << slot;
      bounded_seeds += expected < HUGE_VAL;
      const int seed = c.graph.detected_edges[slot * stride];
      for (; k < gated.candidates().size() && gated.candidates()[k].seed_edge == seed; ++k) {
        const CandidateSummary& s = gated.candidates()[k];
        EXPECT_GT(area_similarity(c.gate.previous_area, s.area), c.gate.min_similarity);
        best = std::min(best, grouping_cost(s.gap_length, s.area));
      }
    }
    EXPECT_EQ(k, gated.candidates().size());

    // Within its bound a seed's trees are the unbounded search's, ties included: every kept
    // candidate is the unbounded search's of the same seed and meeting vertex.
    std::map<std::pair<int, int>, int> unbounded_index;  // (seed, meeting) -> candidate
    for (int i = 0; i < unbounded.size(); ++i) {
      unbounded_index[{unbounded.candidates()[i].seed_edge, unbounded.meeting(i)}] = i;
    }
    std::vector<int> unbounded_cycle;
    for (int i = 0; i < gated.size(); ++i) {
      const auto it = unbounded_index.find({gated.candidates()[i].seed_edge, gated.meeting(i)});
      ASSERT_NE(it, unbounded_index.end()) << "a gated candidate the unbounded search lacks";
      EXPECT_EQ(gated.candidates()[i].gap_length, unbounded.candidates()[it->second].gap_length);
      EXPECT_EQ(gated.candidates()[i].area, unbounded.candidates()[it->second].area);
      gated.vertices(i, &cycle);
      unbounded.vertices(it->second, &unbounded_cycle);
      EXPECT_EQ(cycle, unbounded_cycle) << i;
    }
    // Grid segments tie everywhere: which of several shortest paths the searches pick is theirs,
    // not the reference's, so the rule is checked against the reference on the other kinds.
    if (c.kind == GatedCase::kGrid) continue;

    // The reference under the same limits, then the admissibility and cost filter. The filter
    // compares costs to the last bit (tolerance 0 keeps exact ties only), so it takes the areas
    // CycleSearch computes (same cycle, same seed in the unbounded search; they differ from the
    // reference's shoelace by rounding).
    std::vector<int> meetings;
    std::vector<CycleCandidate> all = reference_candidates(c.graph, stride, &limits, &meetings);
    lost_thirds += unbounded.size() - static_cast<int>(all.size());
    std::map<std::pair<int, int>, double> search_area;  // by (seed, meeting)
    for (int i = 0; i < unbounded.size(); ++i) {
      search_area[{unbounded.candidates()[i].seed_edge, unbounded.meeting(i)}] =
          unbounded.candidates()[i].area;
    }
    for (size_t i = 0; i < all.size(); ++i) {
      CycleCandidate& r = all[i];
      const auto it = search_area.find({r.seed_edge, meetings[i]});
      ASSERT_NE(it, search_area.end()) << "a bounded candidate the unbounded search lacks";
      r.area = it->second;
    }
    std::vector<CycleCandidate> expected;
    double least = HUGE_VAL;
    for (const CycleCandidate& r : all) {
      if (!(area_similarity(c.gate.previous_area, r.area) > c.gate.min_similarity)) continue;
      const double cost = grouping_cost(r.gap_length, r.area);
      if (cost > least * (1.0 + c.gate.tolerance)) continue;
      least = std::min(least, cost);
      expected.push_back(r);
    }
    ASSERT_EQ(gated.size(), static_cast<int>(expected.size()));
    for (int i = 0; i < gated.size(); ++i) {
      EXPECT_EQ(gated.candidates()[i].seed_edge, expected[i].seed_edge) << i;
      EXPECT_EQ(gated.candidates()[i].gap_length, expected[i].gap_length) << i;
      EXPECT_EQ(gated.candidates()[i].area, expected[i].area) << i;
      gated.vertices(i, &cycle);
      EXPECT_EQ(cycle, expected[i].vertices) << i;
    }
  }
  // The bound is exercised: many seeds searched bounded, and some thirds left out by it.
  EXPECT_GT(bounded_seeds, 500);
  EXPECT_GT(lost_thirds, 0);
  std::cout << "[ gate     ] " << bounded_seeds << " bounded seeds, " << lost_thirds
            << " unbounded candidates beyond the bounds\n";
}

// What the tracker sees: StableChooser over the gated candidates against StableChooser over
// the unbounded ones, same previous boundary. The gate can only differ where a near tie is lost
// beyond a bound (see bdsp.h); the rate is printed and held small.
TEST(CandidateGate, ChoosesAsTheUnboundedSearch) {
  CycleSearch unbounded, gated;
  StableChooser chooser;
  std::vector<int> a, b;
  int compared = 0, chosen = 0, mismatches = 0;
  for (unsigned trial = 0; trial < 900; ++trial) {
    GatedCase c = gated_case(trial + 1000u);
    unbounded.run(c.graph, c.options);
    std::mt19937 rng(trial + 77u);
    const Polygon previous = previous_boundary(rng, c, unbounded);
    c.gate.previous_area = area(previous);
    if (!(c.gate.previous_area > 0.0)) continue;
    gated.run(c.graph, c.options, &c.gate);
    const auto list = [](const CycleSearch& s) {
      return [&s](int index, std::vector<int>* out) { s.vertices(index, out); };
    };
    const std::optional<BoundaryChoice> want =
        chooser.choose(unbounded.candidates(), list(unbounded), c.graph, previous,
                       c.gate.min_similarity, c.gate.tolerance);
    const std::optional<BoundaryChoice> got =
        chooser.choose(gated.candidates(), list(gated), c.graph, previous, c.gate.min_similarity,
                       c.gate.tolerance);
    ++compared;
    // A gated choice is never invented: without an unbounded one there is none.
    if (!want) {
      EXPECT_FALSE(got.has_value()) << "trial " << trial;
      continue;
    }
    ++chosen;
    bool same = got.has_value();
    if (same) {
      const CandidateSummary& w = unbounded.candidates()[want->index];
      const CandidateSummary& g = gated.candidates()[got->index];
      unbounded.vertices(want->index, &a);
      gated.vertices(got->index, &b);
      std::sort(a.begin(), a.end());
      std::sort(b.begin(), b.end());
      same = w.gap_length == g.gap_length && std::abs(w.area - g.area) <= 1e-9 * (1.0 + w.area) &&
             a == b;
      EXPECT_LE(got->num_admissible, want->num_admissible);
    }
    mismatches += !same;
  }
  std::cout << "[ gate     ] " << compared << " graphs, " << chosen << " with a choice, "
            << mismatches << " chosen differently\n";
  EXPECT_GT(chosen, 500);
  EXPECT_LE(mismatches, chosen * 3 / 100) << "more than 3% of the choices differ";
}

TEST(Bdsp, NoCandidatesWithoutCycles) {
  // One detected segment: the only other path between its endpoints would be the segment itself.
  EXPECT_TRUE(search_cycle_candidates(build_segment_graph({{{0, 0}, {10, 0}}})).empty());
  EXPECT_TRUE(search_cycle_candidates(build_segment_graph({})).empty());
}

TEST(Bdsp, TriangleOfSegments) {
  // Three sides of a triangle, all detected and touching: one cycle of gap 0, by CycleSearch and
  // by the generic-graph baseline.
  const SegmentGraph graph =
      build_segment_graph({{{0, 0}, {40, 0}}, {{40, 0}, {0, 30}}, {{0, 30}, {0, 0}}});
  BdspOptions options;
  options.seed_stride = 1;
  for (bool generic : {false, true}) {
    SCOPED_TRACE(generic ? "generic graph" : "CycleSearch");
    const std::vector<CycleCandidate> candidates =
        generic ? search_cycle_candidates_generic(graph, options)
                : search_cycle_candidates(graph, options);
    ASSERT_FALSE(candidates.empty());
    for (const CycleCandidate& c : candidates) {
      EXPECT_EQ(c.vertices.size(), 3u);
      EXPECT_EQ(c.gap_length, 0.0);
      EXPECT_DOUBLE_EQ(c.area, 600.0);
    }
  }
}

}  // namespace
}  // namespace scbt
