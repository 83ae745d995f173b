// `scbt eval --gaps` on a rendered dataset: the three variants, the gap's frames left out of the
// scores, the tracker losing the object in the gap and finding it again, and the summary tables.
#include "scbt/app/gap_eval_run.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "scbt/geometry/polygon_io.h"
#include "scbt/testing/test_dataset.h"

namespace scbt {
namespace {
namespace fs = std::filesystem;

const LossRow* find_row(const EvalRunSummary& s, const std::string& tracker) {
  for (const LossRow& row : s.loss) {
    if (row.tracker == tracker) return &row;
  }
  return nullptr;
}

// A rendered box drifting over `frames` frames, written as a dataset under `root` (emptied
// first), and eval options that run `trackers` on it into root/out.
EvalRunOptions drift_dataset(const fs::path& root, int frames,
                             const std::vector<std::string>& trackers) {
  fs::remove_all(root);
  write_synthetic_sequence(root / "data", "Drift", SceneShape::kBox, {120.0, 120.0}, {0.3, 0.1}, 5,
                           frames);
  EvalRunOptions options;
  options.dataset = (root / "data").string();
  options.out = (root / "out").string();
  options.trackers = trackers;
  options.quiet = true;
  options.jobs = 2;
  return options;
}

TEST(GapEvalRunTest, GreyAndDroppedGapsAreLostFoundAgainAndReported) {
  constexpr int kFrames = 140;  // the 60-frame jump from the middle leaves 10 frames after it
  const fs::path root = fs::temp_directory_path() / ("scbt-gap-eval-" + std::to_string(::getpid()));
  const EvalRunOptions options = drift_dataset(root, kFrames, {"bdsp", "static"});
  const GapEvalSummary summary = run_gap_evals(options, std::cerr);

  ASSERT_EQ(summary.runs.size(), 3u);
  EXPECT_EQ(summary.runs[0].variant, "clean");
  EXPECT_EQ(summary.runs[1].variant, "grey30");
  EXPECT_EQ(summary.runs[2].variant, "jump60");
  EXPECT_TRUE(fs::exists(root / "out" / "gaps_summary.md"));
  EXPECT_TRUE(fs::exists(root / "out" / "gaps_summary.csv"));
  // Grey frames are tracked (a line each), dropped ones are not shown (no line).
  EXPECT_EQ(read_text_lines((root / "out" / "grey30" / "bdsp" / "Drift.txt").string()).size(),
            static_cast<size_t>(kFrames));
  EXPECT_EQ(read_text_lines((root / "out" / "jump60" / "bdsp" / "Drift.txt").string()).size(),
            static_cast<size_t>(kFrames - 60));

  const LossRow* clean = find_row(summary.runs[0].summary, "bdsp");
  ASSERT_NE(clean, nullptr);
  EXPECT_EQ(clean->scores.scored, kFrames - 1);  // every frame but the initial one
  EXPECT_EQ(clean->scores.reacquire_delay, -1);  // no gap
  for (size_t v = 1; v < 3; ++v) {
    SCOPED_TRACE(summary.runs[v].variant);
    const LossRow* row = find_row(summary.runs[v].summary, "bdsp");
    ASSERT_NE(row, nullptr);
    EXPECT_EQ(row->scores.scored, kFrames - 1 - (v == 1 ? 30 : 60));
    EXPECT_TRUE(row->has_confidence);
    EXPECT_GE(row->scores.reacquire_delay, 0) << "never found again";
    EXPECT_LE(row->scores.reacquire_delay, 10);
    ASSERT_TRUE(row->scores.success_after.has_value());
    EXPECT_GE(*row->scores.success_after, 0.95);
    // The success rates leave the gap's frames out.
    for (const SequenceScore& s : summary.runs[v].summary.scores) {
      if (s.tracker == "bdsp") {
        EXPECT_EQ(s.errors.frames, kFrames - (v == 1 ? 30 : 60));
      }
    }
    // The static tracker reports no confidence: no AUC.
    const LossRow* fixed = find_row(summary.runs[v].summary, "static");
    ASSERT_NE(fixed, nullptr);
    EXPECT_FALSE(fixed->has_confidence);
  }
  fs::remove_all(root);
}

// Several positions: each variant at each, named by where it starts, its gap where it says.
TEST(GapEvalRunTest, GapsAtSeveralPositionsAreEachRunAndNamed) {
  constexpr int kFrames = 200;
  const fs::path root =
      fs::temp_directory_path() / ("scbt-gap-positions-" + std::to_string(::getpid()));
  const EvalRunOptions options = drift_dataset(root, kFrames, {"bdsp"});
  const GapEvalSummary summary = run_gap_evals(options, std::cerr, {0.2, 0.6});
  ASSERT_EQ(summary.runs.size(), 5u);
  const char* names[] = {"clean", "grey30@0.2", "jump60@0.2", "grey30@0.6", "jump60@0.6"};
  for (size_t v = 0; v < 5; ++v) {
    EXPECT_EQ(summary.runs[v].variant, names[v]);
    EXPECT_TRUE(fs::exists(root / "out" / names[v] / "report.md")) << names[v];
  }
  // Grey frames are tracked (a line each), dropped ones are not (none).
  EXPECT_EQ(read_text_lines((root / "out" / "grey30@0.6" / "bdsp" / "Drift.txt").string()).size(),
            static_cast<size_t>(kFrames));
  EXPECT_EQ(read_text_lines((root / "out" / "jump60@0.2" / "bdsp" / "Drift.txt").string()).size(),
            static_cast<size_t>(kFrames - 60));
  for (size_t v = 1; v < 5; ++v) {
    const LossRow* row = find_row(summary.runs[v].summary, "bdsp");
    ASSERT_NE(row, nullptr);
    EXPECT_GE(row->scores.reacquire_delay, 0) << names[v] << ": never found again";
    EXPECT_LE(row->scores.reacquire_delay, 10) << names[v];
  }
  EXPECT_THROW(run_gap_evals(options, std::cerr, {1.2}), std::invalid_argument);
  EXPECT_THROW(run_gap_evals(options, std::cerr, {0.95}), std::invalid_argument);
  fs::remove_all(root);
}

}  // namespace
}  // namespace scbt
