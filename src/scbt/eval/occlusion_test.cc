#include "scbt/eval/occlusion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/core.hpp>

#include "scbt/eval/perturb.h"

namespace scbt {
namespace {

// A circle of radius 60 drifting right by 0.3 px a frame, over `frames` frames; with
// `approaching`, its radius swings between 60 / 1.6 and 60 x 1.6 every 60 frames (a camera moving
// to and from it, as fast as in the public Bowl sequence).
std::vector<Polygon> drifting_circle(int frames, bool approaching = false) {
  std::vector<Polygon> truth;
  for (int k = 0; k < frames; ++k) {
    Polygon p;
    const double r = approaching ? 60 * std::pow(1.6, std::sin(2 * CV_PI * k / 120)) : 60.0;
    for (int i = 0; i < 48; ++i) {
      const double t = 2 * CV_PI * i / 48;
      p.emplace_back(250 + 0.3 * k + r * std::cos(t), 240 + r * std::sin(t));
    }
    truth.push_back(p);
  }
  return truth;
}

TEST(OcclusionSpec, ParsesAndNamesRoundTrip) {
  for (const char* text :
       {"0.3,2,bar,sweep,solid", "0.4,1.5,disc,stay,textured", "0.2,0.5,hand,stay,solid"}) {
    EXPECT_EQ(parse_occlusion_spec(text).name(), text);
  }
  const OcclusionSpec defaults = parse_occlusion_spec("0.25");
  EXPECT_EQ(defaults.name(), "0.25,2,bar,sweep,solid");
  const Perturbation p = parse_perturbation("occlude:0.4,1,hand,stay,textured");
  EXPECT_EQ(p.kind, PerturbationKind::kOcclude);
  EXPECT_EQ(p.name(), "occlude:0.4,1,hand,stay,textured");
}

TEST(OcclusionSpec, RejectsBadValuesNamingThem) {
  for (const char* bad : {"0.9", "0.01", "x", "0.3,0", "0.3,2,square", "0.3,2,bar,jump",
                          "0.3,2,bar,sweep,striped", "0.3,2,bar,sweep,solid,extra"}) {
    EXPECT_THROW(parse_occlusion_spec(bad), std::invalid_argument) << bad;
  }
  try {
    parse_occlusion_spec("0.3,2,square");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'square'"), std::string::npos) << e.what();
  }
}

class OcclusionPlanTest : public ::testing::TestWithParam<const char*> {};

// Events fall after the first frames, leave frames after the last, hide about `cover` of the
// outline at their worst and nothing between events; the same seed places them the same way.
TEST_P(OcclusionPlanTest, HidesTheCoverAtTheWorstFrameOfEachEvent) {
  const OcclusionSpec spec = parse_occlusion_spec(GetParam());
  const std::vector<Polygon> truth = drifting_circle(600);
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    // The occluder follows the object's scale: while it stays (the middle half of the event), it
    // hides the same fraction of an outline growing or shrinking by 1.6x as of a steady one.
    const OcclusionPlan steady(spec, truth, seed);
    const OcclusionPlan moving(spec, drifting_circle(600, true), seed);
    for (const OcclusionEvent& e : steady.events()) {
      for (int k = e.start + e.length / 4 + 1; k < e.end() - e.length / 4 - 1; ++k) {
        if (spec.motion != OccluderMotion::kStay) break;
        EXPECT_NEAR(moving.hidden_fraction(k), steady.hidden_fraction(k), 0.05)
            << GetParam() << " seed " << seed << " frame " << k;
      }
    }
    const OcclusionPlan plan(spec, truth, seed);
    ASSERT_GE(plan.events().size(), 2u) << seed;
    for (const OcclusionEvent& e : plan.events()) {
      EXPECT_GE(e.start, 15);
      EXPECT_LE(e.end() + 30, 600);
      double worst = 0.0;
      for (int k = e.start; k < e.end(); ++k) worst = std::max(worst, plan.hidden_fraction(k));
      EXPECT_NEAR(worst, spec.cover, 0.06) << GetParam() << " seed " << seed << " at " << e.start;
      EXPECT_EQ(plan.hidden_fraction(e.start - 1), 0.0);
      EXPECT_EQ(plan.hidden_fraction(e.end()), 0.0);
    }
    const OcclusionPlan again(spec, truth, seed);
    ASSERT_EQ(again.events().size(), plan.events().size());
    for (size_t i = 0; i < plan.events().size(); ++i) {
      EXPECT_EQ(again.events()[i].start, plan.events()[i].start);
      EXPECT_EQ(again.events()[i].direction, plan.events()[i].direction);
    }
  }
  EXPECT_NE(OcclusionPlan(spec, truth, 1).events()[0].start,
            OcclusionPlan(spec, truth, 7).events()[0].start);
}

INSTANTIATE_TEST_SUITE_P(Shapes, OcclusionPlanTest,
                         ::testing::Values("0.3,2,bar,sweep,solid", "0.4,1,disc,sweep,solid",
                                           "0.2,2,hand,sweep,textured", "0.3,2,bar,stay,solid",
                                           "0.4,1,disc,stay,textured", "0.3,3,hand,stay,solid"));

// Drawing changes pixels only in event frames, and in grey and colour frames alike.
TEST(OcclusionPlan, DrawsOnlyDuringEvents) {
  const std::vector<Polygon> truth = drifting_circle(300);
  const OcclusionPlan plan(parse_occlusion_spec("0.3,1,bar,sweep,textured"), truth, 5);
  ASSERT_FALSE(plan.events().empty());
  const OcclusionEvent& e = plan.events().front();
  for (int type : {CV_8UC1, CV_8UC3, CV_8UC4}) {
    const cv::Mat blank(480, 640, type, cv::Scalar::all(90));
    cv::Mat before = blank.clone(), during = blank.clone();
    plan.draw(e.start - 1, &before);
    plan.draw(e.start + e.length / 2, &during);
    EXPECT_EQ(cv::norm(before, blank, cv::NORM_INF), 0.0);
    EXPECT_GT(cv::countNonZero(cv::Mat(during != blank).reshape(1)), 500);
  }
}

}  // namespace
}  // namespace scbt
