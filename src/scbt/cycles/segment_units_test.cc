// Contraction of the segment graph: units, their arcs, and that dropping dominated arcs changes
// no distance.
#include "scbt/cycles/segment_units.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <vector>

#include "scbt/graph/segment_graph.h"

namespace scbt {
namespace {

// Random segments in a 200 px square (crossings allowed: the graph does not care); about one in
// three starts where an earlier one ends, so that some vertices join several detected segments.
std::vector<Segment> random_segments(std::mt19937& rng, int count) {
  std::uniform_real_distribution<double> pos(0.0, 200.0);
  std::uniform_int_distribution<int> coin(0, 2);
  std::vector<Segment> segments;
  for (int i = 0; i < count; ++i) {
    Point a(pos(rng), pos(rng));
    if (!segments.empty() && coin(rng) == 0) {
      a = segments[std::uniform_int_distribution<size_t>(0, segments.size() - 1)(rng)].b;
    }
    segments.push_back({a, Point(pos(rng), pos(rng))});
  }
  return segments;
}

// Dijkstra over the units' arcs (a plain O(V^2) one).
std::vector<double> unit_distances(const SegmentUnits& units, int source) {
  const int n = units.num_units;
  std::vector<double> distance(n, std::numeric_limits<double>::infinity());
  std::vector<char> done(n, 0);
  distance[source] = 0.0;
  for (int round = 0; round < n; ++round) {
    int u = -1;
    for (int v = 0; v < n; ++v) {
      if (!done[v] && (u < 0 || distance[v] < distance[u])) u = v;
    }
    if (u < 0 || std::isinf(distance[u])) break;
    done[u] = 1;
    for (int k = units.arc_begin[u]; k < units.arc_begin[u + 1]; ++k) {
      const SegmentUnits::Arc& arc = units.arcs[k];
      distance[arc.unit] = std::min(distance[arc.unit], distance[u] + arc.weight);
    }
  }
  return distance;
}

class SegmentUnitsProperty : public ::testing::TestWithParam<unsigned> {};

TEST_P(SegmentUnitsProperty, UnitsAndArcsDescribeTheGraph) {
  std::mt19937 rng(GetParam() * 7717u + 1u);
  const SegmentGraph graph =
      build_segment_graph(random_segments(rng, std::uniform_int_distribution<int>(2, 60)(rng)));
  SegmentUnits units;
  build_segment_units(graph, &units);
  const int n = graph.num_vertices();
  ASSERT_EQ(static_cast<int>(units.unit_of.size()), n);

  // Detected edges per vertex.
  std::vector<int> detected(n, 0);
  for (int e : graph.detected_edges) {
    ++detected[graph.edges[e].u];
    ++detected[graph.edges[e].v];
  }
  std::vector<int> members(units.num_units, 0);
  int pairs = 0;
  for (int v = 0; v < n; ++v) {
    ASSERT_GE(units.unit_of[v], 0);
    ASSERT_LT(units.unit_of[v], units.num_units);
    ++members[units.unit_of[v]];
    const int p = units.partner[v];
    if (p < 0) continue;
    ++pairs;
    // A two-vertex unit is one detected segment whose ends have no other detected edge.
    EXPECT_EQ(units.partner[p], v);
    EXPECT_EQ(units.unit_of[p], units.unit_of[v]);
    EXPECT_EQ(detected[v], 1);
    EXPECT_EQ(detected[p], 1);
    const bool joined =
        std::any_of(graph.detected_edges.begin(), graph.detected_edges.end(), [&](int e) {
          const GraphEdge& edge = graph.edges[e];
          return (edge.u == v && edge.v == p) || (edge.u == p && edge.v == v);
        });
    EXPECT_TRUE(joined) << v << " " << p;
  }
  for (int u = 0; u < units.num_units; ++u) EXPECT_GE(members[u], 1);
  EXPECT_EQ(units.num_units, n - pairs / 2);

  // One arc per pair of units an edge joins, the lightest of those edges, with its ends.
  for (int x = 0; x < units.num_units; ++x) {
    std::set<int> targets;
    for (int k = units.arc_begin[x]; k < units.arc_begin[x + 1]; ++k) {
      const SegmentUnits::Arc& arc = units.arcs[k];
      EXPECT_NE(arc.unit, x);
      EXPECT_TRUE(targets.insert(arc.unit).second) << "two arcs " << x << " -> " << arc.unit;
      EXPECT_EQ(units.unit_of[arc.from], x);
      EXPECT_EQ(units.unit_of[arc.to], arc.unit);
      double lightest = std::numeric_limits<double>::infinity();
      for (const GraphEdge& e : graph.edges) {
        const int a = units.unit_of[e.u], b = units.unit_of[e.v];
        if ((a == x && b == arc.unit) || (b == x && a == arc.unit)) {
          lightest = std::min(lightest, e.weight);
        }
      }
      EXPECT_EQ(arc.weight, lightest);
      const SegmentUnits::Arc& back = units.arcs[units.reverse[k]];
      EXPECT_EQ(back.unit, x);
      EXPECT_EQ(back.weight, arc.weight);
      if (k > units.arc_begin[x]) {
        EXPECT_LE(units.arcs[k - 1].weight, arc.weight) << "unsorted";
      }
    }
  }
  // Every edge between two units has its arc.
  for (const GraphEdge& e : graph.edges) {
    const int a = units.unit_of[e.u], b = units.unit_of[e.v];
    if (a == b) continue;
    const auto first = units.arcs.begin() + units.arc_begin[a];
    const auto last = units.arcs.begin() + units.arc_begin[a + 1];
    EXPECT_TRUE(
        std::any_of(first, last, [&](const SegmentUnits::Arc& arc) { return arc.unit == b; }));
  }
}

TEST_P(SegmentUnitsProperty, DroppingDominatedArcsKeepsDistances) {
  std::mt19937 rng(GetParam() * 104729u + 7u);
  const SegmentGraph graph =
      build_segment_graph(random_segments(rng, std::uniform_int_distribution<int>(2, 60)(rng)));
  SegmentUnits all;
  build_segment_units(graph, &all);
  SegmentUnits pruned = all;
  // No unit opened: every detour counts.
  drop_dominated_arcs(std::vector<int>(all.num_units, -1), 1e-9, &pruned);
  ASSERT_EQ(pruned.num_units, all.num_units);
  EXPECT_LE(pruned.arcs.size(), all.arcs.size());
  for (int x = 0; x < pruned.num_units; ++x) {
    for (int k = pruned.arc_begin[x]; k < pruned.arc_begin[x + 1]; ++k) {
      EXPECT_EQ(pruned.arcs[pruned.reverse[k]].unit, x);
    }
  }
  for (int source = 0; source < all.num_units; ++source) {
    EXPECT_EQ(unit_distances(pruned, source), unit_distances(all, source)) << source;
  }
}

INSTANTIATE_TEST_SUITE_P(Seeds, SegmentUnitsProperty, ::testing::Range(0u, 40u));

// Three segments around a square, each unit a convex-hull neighbour of the next: the arc from
// the first to the third (a hull side of 10 px) is dominated by the way through the middle one
// (two gaps of 1.4 px), unless the middle unit is opened by a search: that detour enters and
// leaves it by different vertices.
TEST(SegmentUnits, DetourThroughAnOpenedUnitCountsOnlyWhole) {
  const SegmentGraph graph =
      build_segment_graph({{{0, 0}, {10, 0}}, {{11, 1}, {11, 9}}, {{10, 10}, {0, 10}}});
  SegmentUnits units;
  build_segment_units(graph, &units);
  ASSERT_EQ(units.num_units, 3);
  const auto unit_at = [&](const Point& p) {
    const auto it = std::find(graph.vertices.begin(), graph.vertices.end(), p);
    return units.unit_of[it - graph.vertices.begin()];
  };
  const int first = unit_at({0, 0}), middle = unit_at({11, 1}), last = unit_at({0, 10});
  const auto joined = [&](const SegmentUnits& u) {
    for (int k = u.arc_begin[first]; k < u.arc_begin[first + 1]; ++k) {
      if (u.arcs[k].unit == last) return true;
    }
    return false;
  };
  ASSERT_TRUE(joined(units));

  SegmentUnits free = units;
  drop_dominated_arcs({-1, -1, -1}, 1e-9, &free);
  EXPECT_FALSE(joined(free));

  std::vector<int> opened(3, -1);
  opened[middle] = 0;  // opened by one search: the detour (in at one end, out at the other) fails
  SegmentUnits kept = units;
  drop_dominated_arcs(opened, 1e-9, &kept);
  EXPECT_TRUE(joined(kept));
}

}  // namespace
}  // namespace scbt
