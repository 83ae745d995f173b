// The tracking criterion (Eq. 1-2), the stabilised choice and the boundary distance.
#include "scbt/choice/boundary_choice.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "scbt/graph/segment_graph.h"
#include "scbt/reference/plain_choice.h"

namespace scbt {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Eq. 2 is the smaller of the two area ratios; computed with one division it must equal that
// minimum to the last bit, as the similarity gate compares it with a threshold. Areas within a
// few ulps of each other are where the two ratios both round to 1.
TEST(BoundaryChoice, AreaSimilarityIsTheSmallerRatioToTheLastBit) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> area_dist(1e-3, 1e6);
  std::uniform_int_distribution<int> ulps(-4, 4), coin(0, 1);
  for (int i = 0; i < 20000; ++i) {
    const double a = area_dist(rng);
    double b = area_dist(rng);
    if (coin(rng) == 0) {  // nearly equal areas
      b = a;
      for (int k = ulps(rng); k != 0; k += k > 0 ? -1 : 1) {
        b = std::nextafter(b, k > 0 ? 2.0 * a : 0.0);
      }
    }
    EXPECT_EQ(area_similarity(a, b), std::min(a / b, b / a)) << a << " " << b;
  }
}

TEST(BoundaryChoice, GroupingCostAndAreaSimilarity) {
  EXPECT_DOUBLE_EQ(grouping_cost(10.0, 200.0), 0.05);
  EXPECT_DOUBLE_EQ(grouping_cost(0.0, 200.0), 0.0);
  EXPECT_TRUE(std::isinf(grouping_cost(10.0, 0.0)));
  EXPECT_DOUBLE_EQ(area_similarity(100.0, 80.0), 0.8);
  EXPECT_DOUBLE_EQ(area_similarity(80.0, 100.0), 0.8);
  EXPECT_DOUBLE_EQ(area_similarity(50.0, 50.0), 1.0);
  EXPECT_EQ(area_similarity(0.0, 50.0), 0.0);
  EXPECT_EQ(area_similarity(50.0, 0.0), 0.0);

  std::mt19937 rng(99);
  std::uniform_real_distribution<double> area_dist(1.0, 1e5), gap_dist(0.0, 500.0);
  for (int i = 0; i < 200; ++i) {
    const double a = area_dist(rng), b = area_dist(rng), g = gap_dist(rng);
    const double s = area_similarity(a, b);
    EXPECT_GT(s, 0.0);
    EXPECT_LE(s, 1.0);
    EXPECT_DOUBLE_EQ(s, area_similarity(b, a));
    EXPECT_DOUBLE_EQ(s, std::min(a, b) / std::max(a, b));
    EXPECT_DOUBLE_EQ(grouping_cost(g, a), g / a);
  }
}

std::vector<CycleCandidate> random_candidates(std::mt19937& rng, int count) {
  std::uniform_real_distribution<double> area_dist(100.0, 2000.0), gap_dist(0.0, 100.0);
  std::vector<CycleCandidate> candidates(count);
  for (CycleCandidate& c : candidates) {
    c.area = area_dist(rng);
    c.gap_length = gap_dist(rng);
  }
  return candidates;
}

class ChooseBoundaryProperty : public ::testing::TestWithParam<unsigned> {};

TEST_P(ChooseBoundaryProperty, MinimumCostAmongAdmissible) {
  std::mt19937 rng(GetParam() * 17u + 1u);
  std::uniform_int_distribution<int> count(0, 30);
  std::uniform_real_distribution<double> previous_dist(100.0, 2000.0), min_sim(0.0, 0.99);
  const std::vector<CycleCandidate> candidates = random_candidates(rng, count(rng));
  const double previous = previous_dist(rng), min_similarity = min_sim(rng);

  int expected = -1, admissible = 0;
  double best_cost = std::numeric_limits<double>::infinity();
  for (int i = 0; i < static_cast<int>(candidates.size()); ++i) {
    const double s =
        std::min(previous, candidates[i].area) / std::max(previous, candidates[i].area);
    if (!(s > min_similarity)) continue;
    ++admissible;
    const double cost = candidates[i].gap_length / candidates[i].area;
    if (cost < best_cost) {
      best_cost = cost;
      expected = i;
    }
  }
  const std::optional<BoundaryChoice> choice =
      choose_boundary(candidates, previous, min_similarity);
  if (expected < 0) {
    EXPECT_FALSE(choice.has_value());
    return;
  }
  ASSERT_TRUE(choice.has_value());
  EXPECT_EQ(choice->index, expected);
  EXPECT_DOUBLE_EQ(choice->cost, best_cost);
  EXPECT_DOUBLE_EQ(choice->similarity, area_similarity(previous, candidates[expected].area));
  EXPECT_EQ(choice->num_admissible, admissible);
}

INSTANTIATE_TEST_SUITE_P(Seeds, ChooseBoundaryProperty, ::testing::Range(0u, 200u));

TEST(BoundaryChoice, NoneQualifies) {
  std::vector<CycleCandidate> candidates(2);
  candidates[0].area = 50.0;   // similarity 0.5
  candidates[1].area = 400.0;  // similarity 0.25
  EXPECT_FALSE(choose_boundary(candidates, 100.0, 0.9).has_value());
  EXPECT_FALSE(choose_boundary({}, 100.0, 0.0).has_value());
  // The gate is strict: similarity exactly at the bound does not qualify.
  EXPECT_FALSE(choose_boundary(candidates, 100.0, 0.5).has_value());
  EXPECT_TRUE(choose_boundary(candidates, 100.0, 0.49).has_value());
}

TEST(BoundaryChoice, TieGoesToTheMoreSimilar) {
  std::vector<CycleCandidate> candidates(2);
  candidates[0].area = 90.0;
  candidates[0].gap_length = 0.0;
  candidates[1].area = 100.0;
  candidates[1].gap_length = 0.0;
  const auto choice = choose_boundary(candidates, 100.0, 0.5);
  ASSERT_TRUE(choice);
  EXPECT_EQ(choice->index, 1);
}

// A regular n-gon of circumradius r around c.
Polygon regular(int n, Point c, double r, double phase = 0.0) {
  Polygon p;
  for (int i = 0; i < n; ++i) {
    const double t = phase + 2.0 * kPi * i / n;
    p.push_back(c + Point(std::cos(t), std::sin(t)) * r);
  }
  return p;
}

// A graph holding the polygons' vertices, each polygon a candidate with the given gap.
struct HandMade {
  SegmentGraph graph;
  std::vector<CycleCandidate> candidates;
  void add(const Polygon& polygon, double gap) {
    CycleCandidate c;
    for (const Point& p : polygon) {
      c.vertices.push_back(graph.num_vertices());
      graph.vertices.push_back(p);
    }
    c.gap_length = gap;
    c.area = area(polygon);
    candidates.push_back(c);
  }
};

TEST(ChooseBoundaryStable, ZeroToleranceIsThePaperRule) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> pos(100.0, 300.0), radius(20.0, 80.0), gap(0.0, 50.0),
      min_sim(0.0, 0.95);
  std::uniform_int_distribution<int> sides(3, 12), count(1, 12);
  for (int round = 0; round < 100; ++round) {
    HandMade made;
    const int n = count(rng);
    for (int i = 0; i < n; ++i) {
      made.add(regular(sides(rng), Point(pos(rng), pos(rng)), radius(rng)), gap(rng));
    }
    const Polygon previous = regular(sides(rng), Point(pos(rng), pos(rng)), radius(rng));
    const double s = min_sim(rng);
    const auto plain = choose_boundary(made.candidates, area(previous), s);
    const auto stable = choose_boundary_stable(made.candidates, made.graph, previous, s, 0.0);
    ASSERT_EQ(plain.has_value(), stable.has_value());
    if (plain) {
      EXPECT_EQ(plain->index, stable->index);
      EXPECT_EQ(plain->cost, stable->cost);
      EXPECT_EQ(plain->num_admissible, stable->num_admissible);
    }
  }
}

TEST(ChooseBoundaryStable, NearTiePicksTheCandidateClosestToThePrevious) {
  const Polygon previous = regular(4, Point(200, 200), 70.0, kPi / 4);
  HandMade made;
  // Candidate 0: moved 30 px, slightly cheaper. Candidate 1: moved 2 px, 5% more expensive.
  made.add(regular(4, Point(230, 200), 70.0, kPi / 4), 10.0);
  made.add(regular(4, Point(202, 200), 70.0, kPi / 4), 10.5);
  // Candidate 2: right where the previous one was, but far more expensive.
  made.add(previous, 20.0);
  // Candidate 3: free and in place, but far too small to pass the similarity gate.
  made.add(regular(4, Point(200, 200), 20.0, kPi / 4), 0.0);

  const auto paper = choose_boundary_stable(made.candidates, made.graph, previous, 0.9, 0.0);
  ASSERT_TRUE(paper);
  EXPECT_EQ(paper->index, 0);
  const auto tight = choose_boundary_stable(made.candidates, made.graph, previous, 0.9, 0.01);
  ASSERT_TRUE(tight);
  EXPECT_EQ(tight->index, 0);  // 5% is not within 1%
  const auto loose = choose_boundary_stable(made.candidates, made.graph, previous, 0.9, 0.1);
  ASSERT_TRUE(loose);
  EXPECT_EQ(loose->index, 1);
  EXPECT_DOUBLE_EQ(loose->cost, 10.5 / made.candidates[1].area);
  const auto wide = choose_boundary_stable(made.candidates, made.graph, previous, 0.9, 2.0);
  ASSERT_TRUE(wide);
  EXPECT_EQ(wide->index, 2);  // within 3x of the best cost and not moved at all
  // The similarity gate still applies: against a previous boundary of 4x the area nothing
  // qualifies, however wide the tolerance.
  const Polygon big = regular(4, Point(200, 200), 140.0, kPi / 4);
  EXPECT_FALSE(choose_boundary_stable(made.candidates, made.graph, big, 0.9, 2.0).has_value());
}

// A cycle that creeps outward: 10 % more area than the previous boundary and 12 % cheaper, mostly
// for its area (Γ = gap / area). The paper's ranking takes it; with Γ / S^0.5 it costs 8 %
// less instead, a near tie that the previous boundary's own cycle wins.
TEST(ChooseBoundaryStable, SimilarityExponentStopsACycleCreepingOutward) {
  const Polygon previous = regular(6, Point(300, 240), 80.0, 0.3);
  const double gap = 12.0;
  const double scale = std::sqrt(1.1);
  HandMade made;
  made.add(previous, gap);
  made.add(regular(6, Point(300, 240), 80.0 * scale, 0.3), gap * 1.1 * 0.88);
  const double ratio = grouping_cost(made.candidates[1].gap_length, made.candidates[1].area) /
                       grouping_cost(made.candidates[0].gap_length, made.candidates[0].area);
  ASSERT_NEAR(ratio, 0.88, 1e-9);
  const auto paper_ranking =
      choose_boundary_stable(made.candidates, made.graph, previous, 0.9, 0.1);
  ASSERT_TRUE(paper_ranking);
  EXPECT_EQ(paper_ranking->index, 1);
  const auto with_exponent =
      choose_boundary_stable(made.candidates, made.graph, previous, 0.9, 0.1, 0.5);
  ASSERT_TRUE(with_exponent);
  EXPECT_EQ(with_exponent->index, 0);
  // The reported cost stays Γ, the similarity the gate's.
  EXPECT_DOUBLE_EQ(with_exponent->cost, gap / made.candidates[0].area);
  // Without the near-tie rule the exponent alone does not reverse a 12 % lead.
  const auto no_tolerance =
      choose_boundary_stable(made.candidates, made.graph, previous, 0.9, 0.0, 0.5);
  ASSERT_TRUE(no_tolerance);
  EXPECT_EQ(no_tolerance->index, 1);
  // A still boundary (S = 1) is ranked as before: the exponent only weighs a change of area.
  HandMade still;
  still.add(regular(6, Point(302, 240), 80.0, 0.3), gap);
  still.add(regular(6, Point(330, 240), 80.0, 0.3), gap * 0.5);
  for (const double k : {0.0, 0.5, 2.0}) {
    const auto chosen =
        choose_boundary_stable(still.candidates, still.graph, previous, 0.9, 0.1, k);
    ASSERT_TRUE(chosen);
    EXPECT_EQ(chosen->index, 1) << "k " << k;
  }
}

// A rim's outline against a cycle that leaks out through one stretch of it into the background
// (a bulge, 8 % more area, 15 % cheaper): the area weighting does not reverse a lead beyond the
// tolerance, the shape weighting does; and it does not hold back the same rim seen more
// obliquely, whose affine shape is the same.
TEST(ChooseBoundaryStable, ShapeWeightStopsALeakThroughOneStretch) {
  const Polygon previous = regular(24, Point(300, 240), 80.0);
  Polygon leak = previous;
  for (int i = 0; i < 4; ++i) leak[i] = Point(300, 240) + (leak[i] - Point(300, 240)) * 1.25;
  const double gap = 12.0;
  HandMade made;
  made.add(previous, gap);
  made.add(leak, gap * 0.85 * area(leak) / area(previous));
  ASSERT_GT(area_similarity(area(previous), area(leak)), 0.9);
  const ShapeDescriptor reference = affine_shape_descriptor(previous);
  auto choose = [&](const HandMade& m, const RankingWeights& weights) {
    StableChooser chooser;
    return chooser.choose(
        m.candidates, [&](int i, std::vector<int>* out) { *out = m.candidates[i].vertices; },
        m.graph, previous, 0.9, 0.1, nullptr, 0.0, weights);
  };
  EXPECT_EQ(choose(made, {0.5})->index, 1);
  const auto weighed = choose(made, {0.5, 4.0, &reference});
  ASSERT_TRUE(weighed);
  EXPECT_EQ(weighed->index, 0);
  // The reported cost stays Γ.
  EXPECT_DOUBLE_EQ(weighed->cost, gap / made.candidates[0].area);
  // No valid reference: the weight is not applied.
  const ShapeDescriptor none;
  EXPECT_EQ(choose(made, {0.5, 4.0, &none})->index, 1);
  EXPECT_EQ(choose(made, {0.5, 4.0, nullptr})->index, 1);
  // A change of shape within the descriptor's noise does not count.
  const double leak_distance = shape_distance(affine_shape_descriptor(leak), reference);
  ASSERT_GT(leak_distance, RankingWeights().shape_noise);
  EXPECT_EQ(choose(made, {0.5, 4.0, &reference, leak_distance + 0.01})->index, 1);

  // The rim foreshortened by 8 % (the same area within the gate), cheaper: taken either way.
  Polygon oblique;
  for (const Point& p : previous) oblique.emplace_back(p.x, 240 + (p.y - 240) * 0.92);
  HandMade tilted;
  tilted.add(previous, gap);
  tilted.add(oblique, gap * 0.85 * area(oblique) / area(previous));
  EXPECT_EQ(choose(tilted, {0.5})->index, 1);
  EXPECT_EQ(choose(tilted, {0.5, 4.0, &reference})->index, 1);
}

// The usual case: the cheapest candidate keeps the remembered shape (its factor 1), and a near tie
// of another shape, closer to the previous boundary, is no longer a tie once weighed.
TEST(ChooseBoundaryStable, ShapeWeightDropsANearTieOfAnotherShape) {
  const Polygon kept = regular(24, Point(300, 240), 80.0);
  Polygon leak = kept;  // a spike into the background
  leak[0] = Point(300, 240) + (leak[0] - Point(300, 240)) * 1.8;
  const double gap = 12.0;
  HandMade made;
  made.add(kept, gap);
  made.add(leak, gap * 1.05 * area(leak) / area(kept));  // 5 % dearer: a near tie
  const ShapeDescriptor reference = affine_shape_descriptor(kept);
  ASSERT_GT(shape_distance(affine_shape_descriptor(leak), reference), 0.06);
  auto choose = [&](const RankingWeights& weights) {
    StableChooser chooser;
    // The previous boundary is the leak's: the closest of the near ties.
    return chooser.choose(
        made.candidates, [&](int i, std::vector<int>* out) { *out = made.candidates[i].vertices; },
        made.graph, leak, 0.9, 0.1, nullptr, 0.0, weights);
  };
  EXPECT_EQ(choose({0.5})->index, 1);
  EXPECT_EQ(choose({0.5, 4.0, &reference})->index, 0);
}

TEST(BoundaryDistance, IdentitySymmetryAndTranslation) {
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> pos(-100.0, 100.0), radius(5.0, 60.0), angle(-kPi, kPi),
      shift(0.5, 8.0);
  std::uniform_int_distribution<int> sides(3, 16);
  for (int round = 0; round < 100; ++round) {
    const Polygon a = regular(sides(rng), Point(pos(rng), pos(rng)), radius(rng), angle(rng));
    const Polygon b = regular(sides(rng), Point(pos(rng), pos(rng)), radius(rng), angle(rng));
    EXPECT_NEAR(boundary_distance(a, a), 0.0, 1e-9);
    EXPECT_DOUBLE_EQ(boundary_distance(a, b), boundary_distance(b, a));
    EXPECT_GE(boundary_distance(a, b), 0.0);
    // Reversing the vertex order or adding vertices on the edges is the same polyline.
    const Polygon reversed(a.rbegin(), a.rend());
    EXPECT_NEAR(boundary_distance(a, reversed), 0.0, 1e-9);
    // Translating by t moves every point by |t|: the distance is at most |t|.
    const double t_angle = angle(rng), t_length = shift(rng);
    const Point t(std::cos(t_angle) * t_length, std::sin(t_angle) * t_length);
    Polygon moved;
    for (const Point& p : a) moved.push_back(p + t);
    EXPECT_LE(boundary_distance(a, moved), t_length + 1e-9);
    EXPECT_GT(boundary_distance(a, moved), 0.0);
  }
}

TEST(BoundaryDistance, LargeShapesMatchTheirContinuousLimit) {
  // A fine polygonal circle of radius R shifted by |t| << R: the distance at angle theta is about
  // |t| |cos theta|, whose mean over the circle is 2 |t| / pi.
  const Polygon circle = regular(256, Point(0, 0), 300.0);
  for (double d : {1.0, 3.0, 6.0}) {
    for (double direction : {0.0, 0.7, 2.0}) {
      const Point t(std::cos(direction) * d, std::sin(direction) * d);
      Polygon moved;
      for (const Point& p : circle) moved.push_back(p + t);
      EXPECT_NEAR(boundary_distance(circle, moved), 2.0 * d / kPi, 0.05 * d);
    }
    // Concentric circles d apart: the distance is d.
    EXPECT_NEAR(boundary_distance(circle, regular(256, Point(0, 0), 300.0 + d)), d, 0.01 * d);
  }
}

// The stabilised choice written out plainly: every distinct near-tie measured with
// boundary_distance in (area, gap) order, the first closest one wins.
std::optional<BoundaryChoice> reference_stable_choice(const std::vector<CycleCandidate>& candidates,
                                                      const SegmentGraph& graph,
                                                      const Polygon& previous,
                                                      double min_similarity, double tolerance) {
  const double previous_area = area(previous);
  std::optional<BoundaryChoice> best = choose_boundary(candidates, previous_area, min_similarity);
  if (!best || tolerance <= 0.0) return best;
  const double bound = best->cost * (1.0 + tolerance);
  std::vector<int> ties;
  for (int i = 0; i < static_cast<int>(candidates.size()); ++i) {
    const CycleCandidate& c = candidates[i];
    if (area_similarity(previous_area, c.area) > min_similarity &&
        grouping_cost(c.gap_length, c.area) <= bound) {
      ties.push_back(i);
    }
  }
  std::stable_sort(ties.begin(), ties.end(), [&](int l, int r) {
    return candidates[l].area < candidates[r].area ||
           (candidates[l].area == candidates[r].area &&
            candidates[l].gap_length < candidates[r].gap_length);
  });
  double best_distance = std::numeric_limits<double>::infinity();
  for (int i : ties) {
    const double d = boundary_distance(candidate_polygon(graph, candidates[i]), previous);
    if (d < best_distance) {
      best_distance = d;
      best->index = i;
    }
  }
  best->cost = grouping_cost(candidates[best->index].gap_length, candidates[best->index].area);
  best->similarity = area_similarity(previous_area, candidates[best->index].area);
  return best;
}

// Random segments scattered near a jittered polygon, so that BDSP finds many near-tied cycles.
std::vector<Segment> segments_near(const Polygon& outline, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0), jitter(-4.0, 4.0), angle(-kPi, kPi);
  std::vector<Segment> segments;
  const int n = static_cast<int>(outline.size());
  for (int i = 0; i < n; ++i) {
    const Point a = outline[i], b = outline[(i + 1) % n];
    for (double t = 0.0; t < 0.9; t += 0.3) {
      const double t0 = t + 0.05 * unit(rng), t1 = t + 0.2 + 0.05 * unit(rng);
      segments.push_back({a + (b - a) * t0 + Point(jitter(rng), jitter(rng)),
                          a + (b - a) * t1 + Point(jitter(rng), jitter(rng))});
    }
    const Point p = a + Point(jitter(rng), jitter(rng)) * 3.0;
    const double t = angle(rng);
    segments.push_back({p, p + Point(std::cos(t), std::sin(t)) * (5.0 + 15.0 * unit(rng))});
  }
  return segments;
}

// The polygon from its lowest vertex (least y, then x), counter-clockwise in y-down coordinates
// (positive signed area): how the choice describes a cycle whichever seed closed it.
Polygon from_lowest_vertex(const Polygon& polygon) {
  const auto lowest = std::min_element(
      polygon.begin(), polygon.end(),
      [](const Point& a, const Point& b) { return a.y < b.y || (a.y == b.y && a.x < b.x); });
  Polygon out(lowest, polygon.end());
  out.insert(out.end(), polygon.begin(), lowest);
  if (signed_area(out) < 0.0) std::reverse(out.begin() + 1, out.end());
  return out;
}

// The choice with RankingWeights written out over every candidate, whole polygons.
std::optional<BoundaryChoice> reference_weighted_choice(
    const std::vector<CycleCandidate>& candidates, const SegmentGraph& graph,
    const Polygon& previous, double min_similarity, double tolerance,
    const RankingWeights& weights) {
  const double previous_area = area(previous);
  std::vector<double> cost(candidates.size(), std::numeric_limits<double>::infinity());
  double least = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < candidates.size(); ++i) {
    const CycleCandidate& c = candidates[i];
    const double s = area_similarity(previous_area, c.area);
    if (!(s > min_similarity)) continue;
    const double d = std::clamp(
        shape_distance(affine_shape_descriptor(from_lowest_vertex(candidate_polygon(graph, c))),
                       *weights.shape_reference) -
            weights.shape_noise,
        0.0, 1.0);
    cost[i] = grouping_cost(c.gap_length, c.area) / std::pow(s, weights.similarity_exponent) *
              std::exp(weights.shape_weight * d);
    least = std::min(least, cost[i]);
  }
  if (!std::isfinite(least)) return std::nullopt;
  BoundaryChoice best;
  double best_distance = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < candidates.size(); ++i) {
    if (!(cost[i] <= least * (1.0 + tolerance))) continue;
    const double d = boundary_distance(candidate_polygon(graph, candidates[i]), previous);
    if (best.index < 0 || d < best_distance) {
      best_distance = d;
      best.index = static_cast<int>(i);
    }
  }
  return best;
}

class StableChooserProperty : public ::testing::TestWithParam<unsigned> {};

// On BDSP's candidates of random graphs, the cached, pruned chooser picks the cycle the plain
// scan picks, and one chooser reused across frames does so every time.
TEST_P(StableChooserProperty, PicksWhatThePlainScanPicks) {
  std::mt19937 rng(GetParam() * 31u + 7u);
  std::uniform_real_distribution<double> pos(150.0, 250.0), radius(40.0, 90.0), phase(0.0, kPi),
      tolerance(0.0, 0.5), shift(-8.0, 8.0);
  std::uniform_int_distribution<int> sides(3, 9);
  StableChooser chooser;
  for (int frame = 0; frame < 3; ++frame) {
    const Polygon outline = regular(sides(rng), Point(pos(rng), pos(rng)), radius(rng), phase(rng));
    const SegmentGraph graph = build_segment_graph(segments_near(outline, rng));
    const std::vector<CycleCandidate> candidates = search_cycle_candidates(graph);
    Polygon previous = regular(sides(rng), centroid(outline), radius(rng), phase(rng));
    for (Point& p : previous) p += Point(shift(rng), shift(rng));
    const double tol = tolerance(rng);
    const auto expected = reference_stable_choice(candidates, graph, previous, 0.5, tol);
    const auto got = chooser.choose(
        candidates, [&](int i, std::vector<int>* out) { *out = candidates[i].vertices; }, graph,
        previous, 0.5, tol);
    ASSERT_EQ(expected.has_value(), got.has_value());
    if (!expected) continue;
    // The same cycle, or one as close to the previous boundary up to rounding (a cycle reached
    // along different paths can carry a gap summed in another order).
    const CycleCandidate &e = candidates[expected->index], &g = candidates[got->index];
    EXPECT_NEAR(boundary_distance(candidate_polygon(graph, e), previous),
                boundary_distance(candidate_polygon(graph, g), previous), 1e-9);
    EXPECT_NEAR(e.area, g.area, 1e-9 * e.area);
    EXPECT_NEAR(e.gap_length, g.gap_length, 1e-9 * (1.0 + e.gap_length));
    EXPECT_NEAR(expected->cost, got->cost, 1e-9 * expected->cost);
    EXPECT_EQ(expected->num_admissible, got->num_admissible);
    EXPECT_EQ(choose_boundary_stable(candidates, graph, previous, 0.5, tol)->index, got->index);

    // With the ranking weighted (tolerance > 0: the weights act through the near-tie pass); the
    // shape noise 0 weighs every cycle that could tie first, 1 weighs them as the distance order
    // reaches them (the best's factor is then 1), 0.02 either.
    const ShapeDescriptor reference = affine_shape_descriptor(outline);
    for (const double noise : {0.0, 0.02, 1.0}) {
      const RankingWeights weights{0.5, 4.0, &reference, noise};
      const double weighed_tol = std::max(tol, 0.01);
      const auto weighed_expected =
          reference_weighted_choice(candidates, graph, previous, 0.5, weighed_tol, weights);
      const auto weighed = chooser.choose(
          candidates, [&](int i, std::vector<int>* out) { *out = candidates[i].vertices; }, graph,
          previous, 0.5, weighed_tol, nullptr, 0.0, weights);
      ASSERT_EQ(weighed_expected.has_value(), weighed.has_value());
      EXPECT_NEAR(boundary_distance(candidate_polygon(graph, candidates[weighed_expected->index]),
                                    previous),
                  boundary_distance(candidate_polygon(graph, candidates[weighed->index]), previous),
                  1e-9)
          << "shape noise " << noise;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Seeds, StableChooserProperty, ::testing::Range(0u, 60u));

TEST(BoundaryDistanceCache, MatchesBoundaryDistanceOnGraphCyclesAndArbitraryOnes) {
  std::mt19937 rng(123);
  std::uniform_real_distribution<double> pos(150.0, 250.0), radius(40.0, 90.0), phase(0.0, kPi);
  std::uniform_int_distribution<int> sides(3, 9);
  BoundaryDistanceCache cache;
  int measured = 0;
  for (int round = 0; round < 40; ++round) {
    const Polygon outline = regular(sides(rng), Point(pos(rng), pos(rng)), radius(rng), phase(rng));
    const SegmentGraph graph = build_segment_graph(segments_near(outline, rng));
    const std::vector<CycleCandidate> candidates = search_cycle_candidates(graph);
    const Polygon previous = regular(sides(rng), Point(pos(rng), pos(rng)), radius(rng));
    cache.reset(graph, previous);
    for (size_t k = 0; k < candidates.size(); k += 7) {
      const Polygon polygon = candidate_polygon(graph, candidates[k]);
      // Twice: the second answer comes from the cache.
      for (int pass = 0; pass < 2; ++pass) {
        EXPECT_NEAR(cache.boundary_distance(candidates[k].vertices),
                    boundary_distance(polygon, previous), 1e-9);
      }
      ++measured;
    }
    // A cycle through vertices that are not joined by graph edges is measured directly, and
    // walking a cycle backwards changes nothing.
    std::uniform_int_distribution<int> vertex(0, graph.num_vertices() - 1);
    std::vector<int> arbitrary = {vertex(rng), vertex(rng), vertex(rng), vertex(rng)};
    Polygon arbitrary_polygon;
    for (int v : arbitrary) arbitrary_polygon.push_back(graph.vertices[v]);
    EXPECT_NEAR(cache.boundary_distance(arbitrary), boundary_distance(arbitrary_polygon, previous),
                1e-9);
    std::vector<int> backwards(arbitrary.rbegin(), arbitrary.rend());
    EXPECT_NEAR(cache.boundary_distance(backwards), cache.boundary_distance(arbitrary), 1e-9);
  }
  EXPECT_GT(measured, 100);
}

// Distances handed in by the filter change nothing, to the last bit, also when some segments
// are repeated, reversed, of zero length or absent from the list (then the list no longer
// lines up with the graph's detected edges, and no distance may land on the wrong point).
TEST(BoundaryDistanceCache, KnownSegmentDistancesGiveTheSameBits) {
  std::mt19937 rng(321);
  std::uniform_real_distribution<double> pos(150.0, 250.0), radius(40.0, 90.0), phase(0.0, kPi);
  std::uniform_int_distribution<int> sides(3, 9);
  BoundaryDistanceCache plain, primed;
  int compared = 0;
  for (int round = 0; round < 40; ++round) {
    const Polygon outline = regular(sides(rng), Point(pos(rng), pos(rng)), radius(rng), phase(rng));
    std::vector<Segment> segments = segments_near(outline, rng);
    segments.insert(segments.begin() + 2, segments[0]);                            // a repeat
    segments.insert(segments.begin() + 4, Segment{segments[1].b, segments[1].a});  // reversed
    segments.insert(segments.begin() + 5, Segment{segments[3].a, segments[3].a});  // zero length
    const SegmentGraph graph = build_segment_graph(segments);
    const std::vector<CycleCandidate> candidates = search_cycle_candidates(graph);
    const Polygon previous = regular(sides(rng), Point(pos(rng), pos(rng)), radius(rng));
    std::vector<Segment> listed(segments.begin() + (round % 3 == 0 ? 1 : 0), segments.end());
    std::vector<double> distances;
    for (const Segment& s : listed) {
      for (const Point& p : {s.a, s.b, s.midpoint()}) {
        distances.push_back(distance_to_boundary(p, previous));
      }
    }
    const KnownSegmentDistances known{&listed, &distances};
    plain.reset(graph, previous);
    primed.reset(graph, previous, &known);
    for (size_t k = 0; k < candidates.size(); k += 3) {
      const std::vector<int>& cycle = candidates[k].vertices;
      EXPECT_EQ(primed.boundary_distance(cycle), plain.boundary_distance(cycle));
      // The edges the cheap direction finds, handed to the other one, change nothing either.
      std::vector<int> edges = {-7};
      EXPECT_EQ(primed.mean_distance_from_cycle(cycle, &edges),
                plain.mean_distance_from_cycle(cycle));
      ASSERT_EQ(edges.size(), cycle.size() + 1);
      EXPECT_EQ(primed.mean_distance_to_cycle(cycle, &edges[1]),
                plain.mean_distance_to_cycle(cycle));
      ++compared;
    }
  }
  EXPECT_GT(compared, 100);
}

}  // namespace
}  // namespace scbt
