#include "scbt/eval/report.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <sstream>

namespace scbt {
namespace {

std::vector<SequenceScore> random_scores(std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0, 1), ms(0, 40);
  std::uniform_int_distribution<int> frames(1, 2000), kind(0, 5);
  const std::vector<std::string> trackers = {"bdsp", "static", "klt"};
  const std::vector<std::string> sequences = {"Bowl", "MarkCup", "ToolBox", kAllSequences};
  std::vector<SequenceScore> scores;
  for (const std::string& sequence : sequences) {
    for (const std::string& tracker : trackers) {
      SequenceScore s;
      s.tracker = tracker;
      s.sequence = sequence;
      ErrorStats& e = s.errors;
      e.frames = frames(rng);
      e.failures = std::uniform_int_distribution<int>(0, e.frames)(rng);
      e.success_5 = unit(rng) / 3;
      e.success_10 = e.success_5 + unit(rng) / 3;
      e.success_20 = e.success_10 + unit(rng) / 3;
      e.auc = unit(rng);
      const int k = kind(rng);
      e.mean = k == 0 ? std::numeric_limits<double>::quiet_NaN() : 100 * unit(rng);
      e.median = k <= 1 ? std::numeric_limits<double>::infinity() : 100 * unit(rng);
      if (tracker == "bdsp") {
        TimingStats& t = s.timing;
        t.has_timing = true;
        t.tracked = e.frames - 1;
        t.held = std::uniform_int_distribution<int>(0, t.tracked)(rng);
        t.edges = 1000 * unit(rng);
        t.nodes = 200 * unit(rng);
        t.line_ms = ms(rng);
        t.grouping_ms = ms(rng);
        t.track_ms = t.line_ms + t.grouping_ms;
        t.fps = 1000.0 / t.track_ms;
      }
      scores.push_back(s);
    }
  }
  return scores;
}

// Equal within the 10 significant digits the CSV keeps; NaN equals NaN.
void expect_close(double a, double b, const std::string& what) {
  if (std::isnan(a) || std::isnan(b)) {
    EXPECT_TRUE(std::isnan(a) && std::isnan(b)) << what << ": " << a << " vs " << b;
  } else if (std::isinf(a) || std::isinf(b)) {
    EXPECT_EQ(a, b) << what;
  } else {
    EXPECT_NEAR(a, b, 1e-9 * std::max(1.0, std::fabs(a))) << what;
  }
}

TEST(SummaryCsv, RoundTrips) {
  std::mt19937 rng(21);
  for (int trial = 0; trial < 20; ++trial) {
    const std::vector<SequenceScore> scores = random_scores(rng);
    std::stringstream csv;
    write_summary_csv(csv, scores);
    const std::string text = csv.str();
    const std::vector<SequenceScore> back = read_summary_csv(csv);
    ASSERT_EQ(back.size(), scores.size());
    for (size_t i = 0; i < scores.size(); ++i) {
      const SequenceScore &a = scores[i], &b = back[i];
      EXPECT_EQ(a.tracker, b.tracker);
      EXPECT_EQ(a.sequence, b.sequence);
      EXPECT_EQ(a.errors.frames, b.errors.frames);
      EXPECT_EQ(a.errors.failures, b.errors.failures);
      expect_close(a.errors.success_5, b.errors.success_5, "success_5");
      expect_close(a.errors.success_10, b.errors.success_10, "success_10");
      expect_close(a.errors.success_20, b.errors.success_20, "success_20");
      expect_close(a.errors.auc, b.errors.auc, "auc");
      expect_close(a.errors.mean, b.errors.mean, "mean");
      expect_close(a.errors.median, b.errors.median, "median");
      ASSERT_EQ(a.timing.has_timing, b.timing.has_timing);
      if (a.timing.has_timing) {
        EXPECT_EQ(a.timing.tracked, b.timing.tracked);
        EXPECT_EQ(a.timing.held, b.timing.held);
        expect_close(a.timing.edges, b.timing.edges, "edges");
        expect_close(a.timing.nodes, b.timing.nodes, "nodes");
        expect_close(a.timing.line_ms, b.timing.line_ms, "line_ms");
        expect_close(a.timing.grouping_ms, b.timing.grouping_ms, "grouping_ms");
        expect_close(a.timing.track_ms, b.timing.track_ms, "track_ms");
        expect_close(a.timing.fps, b.timing.fps, "fps");
      }
    }
    // Writing what was read gives the same bytes.
    std::stringstream again;
    write_summary_csv(again, back);
    EXPECT_EQ(again.str(), text);
  }
}

TEST(SummaryCsv, RejectsMalformedInput) {
  std::mt19937 rng(22);
  std::stringstream csv;
  write_summary_csv(csv, random_scores(rng));
  const std::string good = csv.str();
  const std::string header = good.substr(0, good.find('\n') + 1);
  std::istringstream empty("");
  EXPECT_THROW(read_summary_csv(empty), std::runtime_error);
  std::istringstream no_column("tracker,sequence\nbdsp,Bowl\n");
  EXPECT_THROW(read_summary_csv(no_column), std::runtime_error);
  std::istringstream short_row(header + "bdsp,Bowl,3\n");
  EXPECT_THROW(read_summary_csv(short_row), std::runtime_error);
  std::istringstream bad_number(header + "bdsp,Bowl,3,0,x,0,0,0,0,0,,,,,,,,\n");
  EXPECT_THROW(read_summary_csv(bad_number), std::runtime_error);
  std::istringstream fractional_count(header + "bdsp,Bowl,3.5,0,0,0,0,0,0,0,,,,,,,,\n");
  EXPECT_THROW(read_summary_csv(fractional_count), std::runtime_error);
  SequenceScore comma;
  comma.tracker = "a,b";
  comma.sequence = "Bowl";
  std::ostringstream out;
  EXPECT_THROW(write_summary_csv(out, {comma}), std::invalid_argument);
}

// The cells of the Markdown table rows that start with "| <sequence> | <tracker> |".
std::vector<std::string> markdown_row(const std::string& markdown, const std::string& section,
                                      const std::string& sequence, const std::string& tracker) {
  const size_t start = markdown.find(section);
  if (start == std::string::npos) return {};
  const std::string prefix = "| " + sequence + " | " + tracker + " |";
  const size_t row = markdown.find(prefix, start);
  if (row == std::string::npos) return {};
  const std::string line = markdown.substr(row, markdown.find('\n', row) - row);
  std::vector<std::string> cells;
  std::stringstream stream(line.substr(1));
  std::string cell;
  while (std::getline(stream, cell, '|')) {
    const size_t a = cell.find_first_not_of(" *"), b = cell.find_last_not_of(" *");
    cells.push_back(a == std::string::npos ? "" : cell.substr(a, b - a + 1));
  }
  return cells;
}

double cell_value(const std::string& cell) {
  if (cell == "-") return std::numeric_limits<double>::quiet_NaN();
  return std::strtod(cell.c_str(), nullptr);
}

TEST(MarkdownReport, TablesShowTheSummaryNumbers) {
  std::mt19937 rng(23);
  for (int trial = 0; trial < 10; ++trial) {
    const std::vector<SequenceScore> scores = random_scores(rng);
    std::ostringstream out;
    ReportInfo info;
    info.dataset = "/data/set";
    info.plot_file = "success_curves.png";
    write_markdown_report(out, scores, info);
    const std::string md = out.str();
    EXPECT_NE(md.find("](success_curves.png)"), std::string::npos);
    for (const SequenceScore& s : scores) {
      const std::string section =
          s.sequence == kAllSequences ? "## All sequences pooled" : "## Success rate per sequence";
      const std::vector<std::string> cells = markdown_row(md, section, s.sequence, s.tracker);
      ASSERT_EQ(cells.size(), 10u) << s.sequence << " " << s.tracker << "\n" << md;
      EXPECT_EQ(std::stoi(cells[2]), s.errors.frames);
      EXPECT_NEAR(cell_value(cells[3]), 100 * s.errors.success_5, 0.05 + 1e-9);
      EXPECT_NEAR(cell_value(cells[4]), 100 * s.errors.success_10, 0.05 + 1e-9);
      EXPECT_NEAR(cell_value(cells[5]), 100 * s.errors.success_20, 0.05 + 1e-9);
      const double mean = cell_value(cells[6]), median = cell_value(cells[7]);
      if (std::isnan(s.errors.mean)) {
        EXPECT_TRUE(std::isnan(mean)) << cells[6];
      } else {
        EXPECT_NEAR(mean, s.errors.mean, 0.005 + 1e-9);
      }
      if (std::isinf(s.errors.median)) {
        EXPECT_EQ(cells[7], "inf");
      } else {
        EXPECT_NEAR(median, s.errors.median, 0.005 + 1e-9);
      }
      EXPECT_NEAR(cell_value(cells[8]), s.errors.auc, 0.0005 + 1e-9);
      EXPECT_EQ(std::stoi(cells[9]), s.errors.failures);
      if (s.timing.has_timing && s.sequence != kAllSequences) {
        const std::vector<std::string> t =
            markdown_row(md, "## Graph scale and time efficiency", s.sequence, s.tracker);
        ASSERT_EQ(t.size(), 9u);
        EXPECT_NEAR(cell_value(t[2]), s.timing.edges, 0.5 + 1e-9);
        EXPECT_NEAR(cell_value(t[3]), s.timing.nodes, 0.5 + 1e-9);
        EXPECT_NEAR(cell_value(t[4]), s.timing.line_ms, 0.005 + 1e-9);
        EXPECT_NEAR(cell_value(t[5]), s.timing.grouping_ms, 0.005 + 1e-9);
        if (s.timing.fps > 10000.0) {
          EXPECT_EQ(t[7], ">10000");
        } else {
          EXPECT_NEAR(cell_value(t[7]), s.timing.fps, 0.05 + 1e-9);
        }
        EXPECT_EQ(t[8], std::to_string(s.timing.held) + "/" + std::to_string(s.timing.tracked));
      }
    }
  }
}

TEST(FrameCsv, QuotesNotesAndLeavesAbsentTimingEmpty) {
  std::ostringstream out;
  FrameRecord ok;
  ok.frame = 1;
  ok.e_al = 0.5;
  FrameRecord failed;
  failed.frame = 2;
  failed.e_al = std::numeric_limits<double>::infinity();
  failed.note = "coordinate \"x\" is not a number";
  write_frame_csv_header(out);
  write_frame_csv_rows(out, "bdsp", "Bowl", {ok, failed});
  EXPECT_EQ(out.str(),
            "tracker,sequence,frame,e_al,held,nodes,edges,line_ms,grouping_ms,track_ms,note\n"
            "bdsp,Bowl,1,0.5,,,,,,,\n"
            "bdsp,Bowl,2,inf,,,,,,,\"coordinate \"\"x\"\" is not a number\"\n");
}

}  // namespace
}  // namespace scbt
