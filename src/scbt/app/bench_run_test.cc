// `scbt bench` on a small dataset rendered in code: what it times, scores and writes.
#include "scbt/app/bench_run.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <random>
#include <sstream>

#include "scbt/geometry/polygon_io.h"
#include "scbt/testing/test_dataset.h"

namespace scbt {
namespace {
namespace fs = std::filesystem;

TEST(TimeStats, NearestRankOrderStatistics) {
  std::mt19937 rng(3);
  for (int round = 0; round < 50; ++round) {
    std::uniform_int_distribution<int> count(1, 300);
    std::vector<double> samples(count(rng));
    std::uniform_real_distribution<double> value(0.0, 10.0);
    for (double& x : samples) x = value(rng);
    const TimeStats stats = time_stats(samples);
    std::vector<double> sorted = samples;
    std::sort(sorted.begin(), sorted.end());
    const size_t n = sorted.size();
    double sum = 0.0;
    for (double x : samples) sum += x;
    EXPECT_NEAR(stats.mean, sum / n, 1e-12);
    EXPECT_EQ(stats.max, sorted.back());
    // Nearest rank: the smallest sample with at least q of the samples at or below it.
    for (auto [q, got] : {std::pair{0.5, stats.median}, {0.9, stats.p90}, {0.99, stats.p99}}) {
      const auto at_or_below =
          std::count_if(sorted.begin(), sorted.end(), [&](double x) { return x <= got; });
      EXPECT_GE(static_cast<double>(at_or_below), q * n - 1e-9);
      const auto below =
          std::count_if(sorted.begin(), sorted.end(), [&](double x) { return x < got; });
      EXPECT_LT(static_cast<double>(below), q * n);
    }
  }
  const TimeStats empty = time_stats({});
  EXPECT_EQ(empty.mean, 0.0);
  EXPECT_EQ(empty.p99, 0.0);
}

class BenchRunTest : public ::testing::Test {
 protected:
  static constexpr int kFrames = 10;

  void SetUp() override {
    root_ = fs::temp_directory_path() /
            ("scbt-bench-run-test-" + std::to_string(::getpid()) + "-" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root_);
    add_sequence("Slide", SceneShape::kBox, {2.0, 1.0}, 21);
    add_sequence("Rim", SceneShape::kRim, {-1.0, 0.0}, 22);
    options_.dataset = (root_ / "data").string();
    options_.quiet = true;
  }
  void TearDown() override { fs::remove_all(root_); }

  void add_sequence(const std::string& name, SceneShape shape, Point shift, std::uint32_t seed) {
    write_synthetic_sequence(root_ / "data", name, shape, {150.0, 120.0}, shift, seed, kFrames);
  }

  fs::path root_;
  BenchRunOptions options_;
};

TEST_F(BenchRunTest, TimesBothConfigurationsStageByStageAndScoresThem) {
  options_.csv = (root_ / "bench.csv").string();
  std::ostringstream log;
  const BenchReport report = run_bench(options_, log);
  ASSERT_EQ(report.sequences.size(), 2u);
  for (const BenchSequenceResult& s : report.sequences) {
    EXPECT_EQ(s.frames, kFrames);
    ASSERT_EQ(s.configs.size(), 2u);
    EXPECT_EQ(s.configs[0].config, "optimised");
    EXPECT_EQ(s.configs[1].config, "straightforward");
    EXPECT_GT(s.peak_rss_kb, 0);
    EXPECT_GT(s.speedup, 0.0);
    for (const BenchConfigResult& c : s.configs) {
      // A clean rendered scene is tracked on every frame by both.
      EXPECT_EQ(c.held, 0) << s.name << " " << c.config;
      EXPECT_DOUBLE_EQ(c.success_10px, 1.0) << s.name << " " << c.config;
      EXPECT_GT(c.mean_detected, 0.0);
      EXPECT_GT(c.line.mean, 0.0);
      EXPECT_GT(c.search.mean, 0.0);
      EXPECT_LE(c.line.median, c.line.p90);
      EXPECT_LE(c.line.p90, c.line.p99);
      // Grouping is the sum of its stages (no frame was lost, so no motion estimate).
      EXPECT_NEAR(c.grouping.mean, c.filter.mean + c.graph.mean + c.search.mean + c.choice.mean,
                  1e-9);
      // The call as a whole takes at least what its stages add up to.
      EXPECT_GE(c.total.mean + 1e-6, c.line.mean + c.grouping.mean);
      EXPECT_NEAR(c.fps, 1000.0 / c.total.mean, 1e-6 * c.fps);
    }
  }
  EXPECT_GT(report.mean_total_ms, 0.0);
  EXPECT_GE(report.slowest_total_ms, report.mean_total_ms);
  EXPECT_GT(report.baseline_mean_total_ms, 0.0);

  const std::vector<std::string> rows = read_text_lines(options_.csv);
  ASSERT_EQ(rows.size(), 1u + 2u * 2u);  // header + sequences x configurations
  const auto columns = [](const std::string& row) {
    return std::count(row.begin(), row.end(), ',');
  };
  for (const std::string& row : rows) EXPECT_EQ(columns(row), columns(rows[0])) << row;
  EXPECT_NE(rows[0].find("search_median_ms"), std::string::npos);

  const std::string table = format_bench_report(report);
  for (const char* expected : {"| Slide | optimised |", "| Rim | straightforward |",
                               "Grouping stage by stage", "Table I style", "straightforward: "}) {
    EXPECT_NE(table.find(expected), std::string::npos) << expected << "\n" << table;
  }
}

TEST_F(BenchRunTest, HonoursSequenceSelectionFrameLimitAndNoComparison) {
  options_.sequences = {"Rim"};
  options_.max_frames = 4;
  options_.compare = false;
  std::ostringstream log;
  const BenchReport report = run_bench(options_, log);
  ASSERT_EQ(report.sequences.size(), 1u);
  EXPECT_EQ(report.sequences[0].name, "Rim");
  EXPECT_EQ(report.sequences[0].frames, 4);
  ASSERT_EQ(report.sequences[0].configs.size(), 1u);
  EXPECT_EQ(report.sequences[0].speedup, 0.0);
  EXPECT_EQ(report.baseline_mean_total_ms, 0.0);
  EXPECT_EQ(format_bench_report(report).find("straightforward"), std::string::npos);
}

TEST_F(BenchRunTest, RejectsBadInputBeforeRunning) {
  std::ostringstream log;
  BenchRunOptions bad = options_;
  bad.dataset.clear();
  EXPECT_THROW(run_bench(bad, log), std::invalid_argument);
  bad = options_;
  bad.max_frames = -1;
  EXPECT_THROW(run_bench(bad, log), std::invalid_argument);
  bad = options_;
  bad.tracker.filter_distance = -5.0;
  EXPECT_THROW(run_bench(bad, log), std::invalid_argument);
  bad = options_;
  bad.sequences = {"NoSuchSequence"};
  EXPECT_ANY_THROW(run_bench(bad, log));
  bad = options_;
  bad.dataset = (root_ / "missing").string();
  EXPECT_ANY_THROW(run_bench(bad, log));
  // Nothing was written for a failed run.
  bad = options_;
  bad.csv = (root_ / "never.csv").string();
  bad.max_frames = -1;
  EXPECT_THROW(run_bench(bad, log), std::invalid_argument);
  EXPECT_FALSE(fs::exists(bad.csv));
}

}  // namespace
}  // namespace scbt
