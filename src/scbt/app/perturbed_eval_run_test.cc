#include "scbt/app/perturbed_eval_run.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "scbt/geometry/polygon_io.h"
#include "scbt/testing/test_dataset.h"

namespace scbt {
namespace {
namespace fs = std::filesystem;

// A rendered box face sliding right by 2 px per frame, in the public dataset layout.
class PerturbedEvalTest : public ::testing::Test {
 protected:
  static constexpr int kFrames = 12;

  void SetUp() override {
    root_ = fs::temp_directory_path() /
            ("scbt-perturbed-eval-test-" + std::to_string(::getpid()) + "-" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root_);
    write_synthetic_sequence(root_ / "data", "Slide", SceneShape::kBox, {130.0, 120.0}, {2.0, 0.0},
                             7, kFrames);
    options_.dataset = (root_ / "data").string();
    options_.out = (root_ / "out").string();
    options_.quiet = true;
    options_.jobs = 1;
    options_.trackers = {"bdsp", "static"};
  }
  void TearDown() override { fs::remove_all(root_); }

  fs::path root_;
  EvalRunOptions options_;
};

const SequenceScore* find_score(const EvalRunSummary& s, const std::string& tracker) {
  for (const SequenceScore& score : s.scores) {
    if (score.tracker == tracker && score.sequence == "Slide") return &score;
  }
  return nullptr;
}

TEST_F(PerturbedEvalTest, OneReportPerPerturbationThenTheSummaryAndPlot) {
  const PerturbedEvalSummary summary = run_perturbed_evals(
      options_, parse_perturbation_list("none stride:3 noise:8 downscale:2"), std::cerr);
  ASSERT_EQ(summary.runs.size(), 4u);
  const fs::path out = options_.out;
  for (const char* folder : {"none", "stride_3", "noise_8", "downscale_2"}) {
    EXPECT_TRUE(fs::exists(out / folder / "report.md")) << folder;
  }
  for (const char* file : {"perturb_summary.md", "perturb_summary.csv", "perturb_levels.png"}) {
    EXPECT_TRUE(fs::exists(out / file)) << file;
  }
  EXPECT_EQ(summary.files.front(), (out / "perturb_summary.md").string());
  EXPECT_FALSE(cv::imread((out / "perturb_levels.png").string()).empty());

  // Every 3rd frame: frames 1, 4, 7, 10 are shown, results have one line each.
  const SequenceScore* strided = find_score(summary.runs[1].summary, "bdsp");
  ASSERT_NE(strided, nullptr);
  EXPECT_EQ(strided->errors.frames, 4);
  EXPECT_EQ(read_text_lines((out / "stride_3" / "bdsp" / "Slide.txt").string()).size(), 4u);
  // The box is tracked through each perturbation; the static floor falls behind the slide.
  for (const PerturbedEvalRun& run : summary.runs) {
    const SequenceScore* bdsp = find_score(run.summary, "bdsp");
    ASSERT_NE(bdsp, nullptr) << run.folder;
    EXPECT_EQ(bdsp->errors.success_10, 1.0) << run.folder;
  }
  // Downscaled results are scaled back to full size: the first line is the truth's first.
  const std::vector<std::string> truth = read_text_lines(
      (root_ / "data" / "GroundTruthByPolygons" / "Slide_TrackingGroundTruth.txt").string());
  const Polygon first_truth = parse_polygon_line(truth.front());
  const Polygon first_result = parse_polygon_line(
      read_text_lines((out / "downscale_2" / "bdsp" / "Slide.txt").string()).front());
  ASSERT_EQ(first_result.size(), first_truth.size());
  for (size_t i = 0; i < first_truth.size(); ++i) {
    EXPECT_NEAR(first_result[i].x, first_truth[i].x, 0.01);
    EXPECT_NEAR(first_result[i].y, first_truth[i].y, 0.01);
  }
}

// An occluder's spec holds commas: the summary quotes it, so every row keeps its 9 columns.
TEST_F(PerturbedEvalTest, SummaryRowsKeepTheirColumnsWhenASpecHoldsCommas) {
  options_.trackers = {"static"};
  run_perturbed_evals(options_, parse_perturbation_list("occlude:0.3,1,bar,sweep,solid"),
                      std::cerr);
  const std::vector<std::string> rows =
      read_text_lines((fs::path(options_.out) / "perturb_summary.csv").string());
  ASSERT_EQ(rows.size(), 2u);  // header, Slide
  for (const std::string& row : rows) {
    // Commas outside quotes.
    int separators = 0;
    bool quoted = false;
    for (char c : row) {
      if (c == '"') quoted = !quoted;
      separators += !quoted && c == ',' ? 1 : 0;
    }
    EXPECT_EQ(separators, 8) << row;
  }
  EXPECT_EQ(rows[1].rfind("\"occlude:0.3,1,bar,sweep,solid\",static,Slide,", 0), 0u) << rows[1];
}

TEST_F(PerturbedEvalTest, RejectsRepeatsAndEmptyLists) {
  EXPECT_THROW(run_perturbed_evals(options_, parse_perturbation_list("noise:5 noise:5"), std::cerr),
               std::invalid_argument);
  EXPECT_THROW(run_perturbed_evals(options_, {}, std::cerr), std::invalid_argument);
  EXPECT_FALSE(fs::exists(options_.out));
}

}  // namespace
}  // namespace scbt
