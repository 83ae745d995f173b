// Loss handling end to end on rendered scenes in which the object disappears and comes back
// (synthetic/gap_scene.h): it must be declared lost within a few frames, never reported as
// tracked on a wrong boundary meanwhile, and found again soon after it is back.
#include <gtest/gtest.h>

#include <sstream>
#include <tuple>

#include "scbt/synthetic/gap_scene.h"
#include "scbt/tracker/tracker.h"

namespace scbt {
namespace {

// A boundary this far (symmetric mean distance, px) from the truth is wrong (the E_AL bound of a
// failed frame in the evaluation).
constexpr double kWrongPx = 10.0;

struct GapRun {
  GapScene scene;
  std::vector<TrackResult> results;  // per frame; frame 0 is the initial one (default result)
};

GapRun track_gap_scene(GapKind kind, SceneShape shape, std::uint32_t seed, int gap) {
  SceneOptions scene;
  scene.seed = seed;
  scene.shape = shape;
  scene.object_size = 60.0;
  GapSceneOptions options;
  options.kind = kind;
  options.gap = gap;
  GapRun run{render_gap_scene(scene, options), {}};
  Tracker tracker;
  tracker.init(run.scene.frames[0].image, run.scene.frames[0].truth);
  run.results.emplace_back();
  for (size_t k = 1; k < run.scene.frames.size(); ++k) {
    run.results.push_back(tracker.track(run.scene.frames[k].image));
  }
  return run;
}

std::string describe(const GapRun& run) {
  std::ostringstream out;
  for (size_t k = 1; k < run.results.size(); ++k) {
    const TrackResult& r = run.results[k];
    out << k
        << (run.scene.hidden[k]          ? "H"
            : run.scene.partly_hidden[k] ? "p"
                                         : "")
        << ":" << to_string(r.state)[0] << "/" << static_cast<int>(100 * r.confidence) << "/"
        << static_cast<int>(mean_boundary_distance(r.boundary, run.scene.frames[k].truth)) << " ";
  }
  return out.str();
}

class TrackerLossTest
    : public ::testing::TestWithParam<std::tuple<GapKind, SceneShape, std::uint32_t, int>> {};

TEST_P(TrackerLossTest, LostDuringTheGapAndFoundAgainAfterIt) {
  const auto [kind, shape, seed, gap] = GetParam();
  const GapRun run = track_gap_scene(kind, shape, seed, gap);
  const std::string trace = describe(run);
  SCOPED_TRACE(trace);
  const int n = static_cast<int>(run.results.size());
  int first_hidden = -1;
  for (int k = 0; k < n && first_hidden < 0; ++k) {
    if (run.scene.hidden[k]) first_hidden = k;
  }
  ASSERT_GT(first_hidden, 0);

  // Lost within a few frames of the object being wholly hidden (misses_to_lost = 3).
  int first_lost = -1;
  for (int k = 1; k < n && first_lost < 0; ++k) {
    if (run.results[k].state == TrackState::kLost) first_lost = k;
  }
  ASSERT_GE(first_lost, 0);
  EXPECT_LE(first_lost, first_hidden + 3);

  // Never a confident wrong boundary: no `tracking` frame while hidden, and a `tracking` frame
  // while partly hidden only on the right boundary.
  for (int k = 1; k < run.scene.first_back; ++k) {
    if (run.results[k].state != TrackState::kTracking) continue;
    EXPECT_FALSE(run.scene.hidden[k]) << "frame " << k;
    EXPECT_LT(mean_boundary_distance(run.results[k].boundary, run.scene.frames[k].truth), kWrongPx)
        << "frame " << k;
  }

  // Found again within 5 frames of coming back, then followed within 2 px on average.
  int found = -1;
  for (int k = run.scene.first_back; k < n && found < 0; ++k) {
    if (run.results[k].state == TrackState::kTracking) found = k;
  }
  ASSERT_GE(found, 0);
  EXPECT_LT(found - run.scene.first_back, 5);
  // Found again by a search while lost, and said so.
  if (run.results[found - 1].state == TrackState::kLost) {
    EXPECT_TRUE(run.results[found].step == SearchStep::kInPlace ||
                run.results[found].step == SearchStep::kWholeFrame)
        << step_name(run.results[found].step);
  }
  double sum = 0.0;
  for (int k = found; k < n; ++k) {
    sum += mean_boundary_distance(run.results[k].boundary, run.scene.frames[k].truth);
  }
  EXPECT_LT(sum / (n - found), 2.0);
}

INSTANTIATE_TEST_SUITE_P(
    Gaps, TrackerLossTest,
    ::testing::Combine(::testing::Values(GapKind::kOccluder, GapKind::kExit, GapKind::kBlank),
                       ::testing::Values(SceneShape::kRim, SceneShape::kBox, SceneShape::kPolygon),
                       ::testing::Values(1u, 2u), ::testing::Values(10, 40)),
    [](const ::testing::TestParamInfo<TrackerLossTest::ParamType>& info) {
      return to_string(std::get<0>(info.param)) + "_" + to_string(std::get<1>(info.param)) +
             "_seed" + std::to_string(std::get<2>(info.param)) + "_gap" +
             std::to_string(std::get<3>(info.param));
    });

}  // namespace
}  // namespace scbt
