#include "scbt/app/eval_run.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "scbt/app/ci_requirement.h"
#include "scbt/eval/alignment_error.h"
#include "scbt/geometry/polygon_io.h"
#include "scbt/testing/test_dataset.h"

namespace scbt {
namespace {
namespace fs = std::filesystem;

std::vector<std::string> lines_of(const fs::path& path) { return read_text_lines(path.string()); }

std::string cli_text(const fs::path& path) {
  std::stringstream text;
  text << std::ifstream(path, std::ios::binary).rdbuf();
  return text.str();
}

const SequenceScore* find_score(const std::vector<SequenceScore>& scores,
                                const std::string& tracker, const std::string& sequence) {
  for (const SequenceScore& s : scores) {
    if (s.tracker == tracker && s.sequence == sequence) return &s;
  }
  return nullptr;
}

// A small dataset in the public layout, rendered in code: a box face sliding right by 2 px per
// frame ("Slide") and a rim standing still ("Still").
class EvalRunTest : public ::testing::Test {
 protected:
  static constexpr int kFrames = 12;

  void SetUp() override {
    root_ = fs::temp_directory_path() /
            ("scbt-eval-run-test-" + std::to_string(::getpid()) + "-" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root_);
    add_sequence("Slide", SceneShape::kBox, {2.0, 0.0}, 7);
    add_sequence("Still", SceneShape::kRim, {0.0, 0.0}, 8);
    options_.dataset = (root_ / "data").string();
    options_.out = (root_ / "out").string();
    options_.quiet = true;
    options_.jobs = 2;
  }
  void TearDown() override { fs::remove_all(root_); }

  void add_sequence(const std::string& name, SceneShape shape, Point shift, std::uint32_t seed) {
    write_synthetic_sequence(root_ / "data", name, shape, {130.0, 120.0}, shift, seed, kFrames);
  }

  fs::path root_;
  EvalRunOptions options_;
};

TEST_F(EvalRunTest, RunsTrackersAndWritesEveryOutput) {
  options_.trackers = {"static", "bdsp"};
  const EvalRunSummary summary = run_eval(options_, std::cerr);
  EXPECT_EQ(summary.jobs, 4);
  const fs::path out = options_.out;
  for (const char* file :
       {"report.md", "summary.csv", "frames.csv", "curves.csv", "success_curves.png"}) {
    EXPECT_TRUE(fs::exists(out / file)) << file;
  }
  // Results: one line per frame, frame 1 = the initial (ground-truth) polygon.
  const std::vector<std::string> truth =
      lines_of(root_ / "data" / "GroundTruthByPolygons" / "Slide_TrackingGroundTruth.txt");
  for (const char* tracker : {"static", "bdsp"}) {
    const std::vector<std::string> results = lines_of(out / tracker / "Slide.txt");
    ASSERT_EQ(results.size(), static_cast<size_t>(kFrames)) << tracker;
    EXPECT_EQ(results[0], format_polygon_line(parse_polygon_line(truth[0])));
  }
  // The static tracker repeats frame 1: on the still rim its error stays below a pixel, on the
  // box sliding 2 px a frame it grows (the box's vertical sides are up to 22 px off by the end,
  // its horizontal sides stay close, hence a mean of a few pixels); every frame is scored.
  const SequenceScore* slide = find_score(summary.scores, "static", "Slide");
  const SequenceScore* still = find_score(summary.scores, "static", "Still");
  ASSERT_TRUE(slide && still);
  EXPECT_EQ(slide->errors.frames, kFrames);
  EXPECT_EQ(slide->errors.failures, 0);
  EXPECT_LT(still->errors.mean, 1.0);
  EXPECT_GT(slide->errors.mean, still->errors.mean + 2.0);
  EXPECT_GT(still->errors.auc, slide->errors.auc);
  EXPECT_TRUE(slide->timing.has_timing);
  EXPECT_EQ(slide->timing.tracked, kFrames - 1);
  EXPECT_EQ(slide->timing.held, kFrames - 1);
  // Pooled rows: every frame of both sequences.
  const SequenceScore* pooled = find_score(summary.scores, "bdsp", kAllSequences);
  ASSERT_TRUE(pooled);
  EXPECT_EQ(pooled->errors.frames, 2 * kFrames);
  // The summary CSV holds exactly what was returned.
  std::ifstream csv(out / "summary.csv");
  const std::vector<SequenceScore> back = read_summary_csv(csv);
  ASSERT_EQ(back.size(), summary.scores.size());
  for (size_t i = 0; i < back.size(); ++i) {
    EXPECT_EQ(back[i].tracker, summary.scores[i].tracker);
    EXPECT_EQ(back[i].sequence, summary.scores[i].sequence);
    EXPECT_NEAR(back[i].errors.auc, summary.scores[i].errors.auc, 1e-9);
  }
  // The per-frame CSV: a header and one row per scored frame.
  EXPECT_EQ(lines_of(out / "frames.csv").size(), 1u + 4u * kFrames);
}

TEST_F(EvalRunTest, ScoringWrittenResultsReproducesTheRun) {
  options_.trackers = {"static"};
  const EvalRunSummary run = run_eval(options_, std::cerr);
  EvalRunOptions score = options_;
  score.trackers.clear();
  score.results = {"again=" + (fs::path(options_.out) / "static").string()};
  score.out = (root_ / "scored").string();
  const EvalRunSummary scored = run_eval(score, std::cerr);
  EXPECT_FALSE(fs::exists(root_ / "scored" / "again")) << "nothing is run with --results";
  for (const char* sequence : {"Slide", "Still", kAllSequences}) {
    const SequenceScore* a = find_score(run.scores, "static", sequence);
    const SequenceScore* b = find_score(scored.scores, "again", sequence);
    ASSERT_TRUE(a && b) << sequence;
    EXPECT_EQ(a->errors.frames, b->errors.frames);
    EXPECT_DOUBLE_EQ(a->errors.mean, b->errors.mean);
    EXPECT_DOUBLE_EQ(a->errors.auc, b->errors.auc);
    EXPECT_FALSE(b->timing.has_timing);
  }
}

TEST_F(EvalRunTest, BrokenAndMissingResultLinesAreFailures) {
  // Truth lines as results, except: a count not matching its coordinates on frame 2, a
  // degenerate polygon on frame 3, and the last 4 frames missing.
  const fs::path dir = root_ / "tool";
  fs::create_directories(dir);
  std::vector<std::string> lines =
      lines_of(root_ / "data" / "GroundTruthByPolygons" / "Slide_TrackingGroundTruth.txt");
  lines[1] = "5 1 2 3 4";
  lines[2] = "3 10 10 20 20 30 30";
  lines.resize(kFrames - 4);
  std::ofstream file(dir / "Slide.txt");
  for (const std::string& line : lines) file << line << '\n';
  file.close();
  options_.results = {"tool=" + dir.string()};
  options_.sequences = {"Slide", "Still"};
  const EvalRunSummary summary = run_eval(options_, std::cerr);
  const SequenceScore* slide = find_score(summary.scores, "tool", "Slide");
  const SequenceScore* still = find_score(summary.scores, "tool", "Still");
  ASSERT_TRUE(slide && still);
  EXPECT_EQ(slide->errors.failures, 2 + 4);
  EXPECT_DOUBLE_EQ(slide->errors.mean, 0.0);  // the other lines are the truth itself
  EXPECT_EQ(still->errors.failures, kFrames) << "no Still.txt: every frame fails";
  EXPECT_EQ(summary.warnings.size(), 2u);
  // The reasons are in the per-frame CSV.
  const std::vector<std::string> frames = lines_of(fs::path(options_.out) / "frames.csv");
  EXPECT_NE(frames[2].find("needs 10 coordinates"), std::string::npos) << frames[2];
  EXPECT_NE(frames[kFrames].find("missing result line"), std::string::npos) << frames[kFrames];
}

TEST_F(EvalRunTest, RejectsBadInputBeforeRunning) {
  EvalRunOptions bad = options_;
  bad.trackers = {"nope"};
  EXPECT_THROW(run_eval(bad, std::cerr), std::invalid_argument);
  bad = options_;
  bad.sequences = {"Missing"};
  EXPECT_THROW(run_eval(bad, std::cerr), std::invalid_argument);
  bad = options_;
  bad.dataset = (root_ / "nowhere").string();
  EXPECT_THROW(run_eval(bad, std::cerr), std::runtime_error);
  bad = options_;
  bad.results = {"x=" + (root_ / "nowhere").string()};
  EXPECT_THROW(run_eval(bad, std::cerr), std::runtime_error);
  bad = options_;
  bad.results = {"noequals"};
  EXPECT_THROW(run_eval(bad, std::cerr), std::invalid_argument);
  bad = options_;
  bad.trackers = {"static"};
  bad.results = {"static=" + root_.string()};
  EXPECT_THROW(run_eval(bad, std::cerr), std::invalid_argument);
  bad = options_;
  bad.out.clear();
  EXPECT_THROW(run_eval(bad, std::cerr), std::invalid_argument);
  EXPECT_FALSE(fs::exists(options_.out)) << "nothing written by a rejected run";
}

std::string eval_error(const EvalRunOptions& options) {
  try {
    run_eval(options, std::cerr);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(not refused)";
}

// The results being scored are never overwritten by the trackers being run: refused before any
// work, both paths named.
TEST_F(EvalRunTest, RefusesToOverwriteTheResultsItScores) {
  options_.trackers = {"static"};
  run_eval(options_, std::cerr);
  const fs::path scored = fs::path(options_.out) / "static" / "Slide.txt";
  const std::string before = cli_text(scored);
  EvalRunOptions again = options_;
  again.results = {"mine=" + (fs::path(options_.out) / "static").string()};
  const std::string message = eval_error(again);
  EXPECT_NE(message.find("--out " + scored.string() +
                         " is the same file as --results mine=" + scored.string()),
            std::string::npos)
      << message;
  EXPECT_EQ(cli_text(scored), before);
}

TEST_F(EvalRunTest, RefusesAnOutputFolderInsideTheDataset) {
  options_.trackers = {"static"};
  options_.out = (root_ / "data" / "GroundTruthByPolygons" / "..").string();
  EXPECT_NE(eval_error(options_).find("is inside --dataset"), std::string::npos);
  options_.out = (root_ / "data" / "results").string();
  EXPECT_NE(eval_error(options_).find("--out " + options_.out + " is inside --dataset " +
                                      options_.dataset + "; refusing to write into it"),
            std::string::npos)
      << eval_error(options_);
  EXPECT_FALSE(fs::exists(options_.out));
}

// Results files are read with a limit: an endless one (a link to /dev/zero) fails its job with
// the limit named, instead of filling the memory.
TEST_F(EvalRunTest, AnEndlessResultsFileHitsTheLimit) {
  const fs::path dir = root_ / "endless";
  fs::create_directories(dir);
  fs::create_symlink("/dev/zero", dir / "Slide.txt");
  options_.results = {"endless=" + dir.string()};
  options_.sequences = {"Slide"};
  try {
    run_eval(options_, std::cerr);
    FAIL() << "not refused";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("larger than 256 MiB, the limit for a results file"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(EvalRunTest, AFailedJobLeavesNoResultsButTheOthersAreReported) {
  std::ofstream(root_ / "data" / "OriginalVideosAVI" / "Slide" / "0005.png") << "not a png";
  options_.trackers = {"static"};
  try {
    run_eval(options_, std::cerr);
    FAIL() << "a job with an undecodable frame did not fail the run";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("1 of 2 jobs failed"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("0005.png"), std::string::npos) << e.what();
  }
  const fs::path out = options_.out;
  EXPECT_FALSE(fs::exists(out / "static" / "Slide.txt")) << "partial results left behind";
  EXPECT_TRUE(fs::exists(out / "static" / "Still.txt"));
  std::ifstream csv(out / "summary.csv");
  const std::vector<SequenceScore> scores = read_summary_csv(csv);
  ASSERT_EQ(scores.size(), 1u) << "only Still is scored, and no pooled row over a failed job";
  EXPECT_EQ(scores[0].sequence, "Still");
  std::stringstream report;
  report << std::ifstream(out / "report.md").rdbuf();
  EXPECT_NE(report.str().find("FAILED: static/Slide"), std::string::npos) << report.str();
}

TEST_F(EvalRunTest, ProgressNamesEveryJob) {
  options_.trackers = {"static"};
  options_.quiet = false;
  std::ostringstream log;
  run_eval(options_, log);
  EXPECT_NE(log.str().find("static   Slide"), std::string::npos) << log.str();
  EXPECT_NE(log.str().find("static   Still"), std::string::npos) << log.str();
  EXPECT_NE(log.str().find("/2]"), std::string::npos) << log.str();
}

// On the real dataset (when present): the first frames of one sequence, bdsp against static.
TEST(EvalRunDataset, BdspBeatsTheStaticFloorOnTheFirstFrames) {
  SCBT_REQUIRE_DATASET(dataset);
  EvalRunOptions options;
  options.dataset = dataset;
  options.sequences = {"Bowl"};
  options.trackers = {"bdsp", "static"};
  options.max_frames = 60;
  options.quiet = true;
  options.out =
      (fs::temp_directory_path() / ("scbt-eval-dataset-" + std::to_string(::getpid()))).string();
  const EvalRunSummary summary = run_eval(options, std::cerr);
  fs::remove_all(options.out);
  const SequenceScore* bdsp = find_score(summary.scores, "bdsp", "Bowl");
  const SequenceScore* fixed = find_score(summary.scores, "static", "Bowl");
  ASSERT_TRUE(bdsp && fixed);
  EXPECT_EQ(bdsp->errors.frames, 60);
  EXPECT_EQ(bdsp->errors.failures, 0);
  EXPECT_GT(bdsp->errors.auc, fixed->errors.auc);
  EXPECT_GT(bdsp->timing.edges, 0.0);
}

}  // namespace
}  // namespace scbt
