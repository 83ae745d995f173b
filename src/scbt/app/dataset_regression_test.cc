// End-to-end accuracy regression on the public dataset: scbt's default tracker, run by the same
// code as `scbt eval` over every frame, must keep each sequence's success rate at 10 px and at
// 5 px (E_AL < 10, < 5) at or above a floor and its mean E_AL at or below a ceiling. The limits
// are the figures measured on this code minus the margin stated at the table; a crossed limit
// prints the frames that fail it. Missing dataset: skipped, failed under CI=true
// (ci_requirement.h).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "scbt/app/ci_requirement.h"
#include "scbt/app/eval_run.h"

namespace scbt {
namespace {

struct Limits {
  double success_10 = 0.0;  // floor
  double success_5 = 0.0;   // floor
  double mean = 0.0;        // ceiling, px
};

// Measured (comment of each row: S@10, S@5, mean E_AL, frames scored) and the limits: 3 more
// frames at or over 10 px than today, 6 more at or over 5 px, the mean 0.08 px higher. The
// tracker is deterministic for a given binary: two runs of one build give the same figures to the
// last digit, and the ASan build (gcc -O1, scripts/ci_sanitizers.sh) gives the same figures as
// the Release build. The margin is for what can still differ on another machine (its CPU's code
// paths, another compiler's floating point): a frame or two that sits at a threshold. A frame lost
// for good costs about 0.06 px of the mean over ~1000 frames, so the ceiling also catches a few
// frames of a lost object.
const std::map<std::string, Limits>& limits() {
  static const std::map<std::string, Limits> table = {
      {"BookStand", {0.9955, 0.9866, 1.611}},       // .9989 .9933 1.531 px, 899
      {"Bowl", {0.9962, 0.9860, 1.263}},            // .9991 .9917 1.183 px, 1079
      {"MarkCup", {0.9953, 0.9720, 1.560}},         // .9988 .9790 1.480 px, 859
      {"MarkCupContour", {0.9975, 0.9951, 1.829}},  // 1     1     1.749 px, 1226
      {"ToolBox", {0.9964, 0.9850, 1.519}},         // .9991 .9903 1.439 px, 1135
      {"TransparentCup", {0.9971, 0.9857, 1.305}},  // 1     .9914 1.225 px, 1051
  };
  return table;
}

// frame -> E_AL of one (tracker, sequence) from frames.csv.
std::map<int, double> frame_errors(const std::filesystem::path& csv, const std::string& tracker,
                                   const std::string& sequence) {
  std::map<int, double> errors;
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // header: tracker,sequence,frame,e_al,...
  while (std::getline(in, line)) {
    std::stringstream fields(line);
    std::string t, s, frame, e_al;
    if (!std::getline(fields, t, ',') || !std::getline(fields, s, ',') ||
        !std::getline(fields, frame, ',') || !std::getline(fields, e_al, ',')) {
      continue;
    }
    if (t == tracker && s == sequence) errors[std::stoi(frame)] = std::stod(e_al);
  }
  return errors;
}

// "frame (E_AL)" of the frames at or over `threshold`, the worst first, at most 60.
std::string frames_at_or_over(const std::map<int, double>& errors, double threshold) {
  std::vector<std::pair<double, int>> over;
  for (const auto& [frame, e_al] : errors) {
    if (!(e_al < threshold)) over.emplace_back(e_al, frame);
  }
  std::sort(over.rbegin(), over.rend());
  std::ostringstream list;
  list << std::setprecision(4) << over.size() << " frames:";
  for (size_t i = 0; i < over.size() && i < 60; ++i) {
    list << ' ' << over[i].second << " (" << over[i].first << ')';
  }
  if (over.size() > 60) list << " ...";
  return list.str();
}

TEST(DatasetRegression, AccuracyStaysWithinLimits) {
  SCBT_REQUIRE_DATASET(dataset);
  EvalRunOptions options;
  options.dataset = dataset;
  options.trackers = {"bdsp"};
  options.out = (std::filesystem::path(::testing::TempDir()) /
                 ("scbt_dataset_regression_" + std::to_string(::getpid())))
                    .string();
  options.quiet = true;
  options.plot = false;
  std::ostringstream log;
  const EvalRunSummary summary = run_eval(options, log);
  const std::filesystem::path frames_csv = std::filesystem::path(options.out) / "frames.csv";

  int checked = 0;
  for (const SequenceScore& score : summary.scores) {
    if (score.tracker != "bdsp" || score.sequence == kAllSequences) continue;
    const auto limit = limits().find(score.sequence);
    std::printf("%-15s S@10 %.4f  S@5 %.4f  mean E_AL %.3f px  (%d frames, %d failures)\n",
                score.sequence.c_str(), score.errors.success_10, score.errors.success_5,
                score.errors.mean, score.errors.frames, score.errors.failures);
    if (limit == limits().end()) {
      ADD_FAILURE() << score.sequence << " has no limits";
      continue;
    }
    ++checked;
    const Limits& l = limit->second;
    if (score.errors.success_10 < l.success_10) {
      ADD_FAILURE() << std::setprecision(4) << score.sequence << ": S@10 "
                    << score.errors.success_10 << " under its floor " << l.success_10
                    << "; E_AL >= 10 px on "
                    << frames_at_or_over(frame_errors(frames_csv, "bdsp", score.sequence), 10.0);
    }
    if (score.errors.success_5 < l.success_5) {
      ADD_FAILURE() << std::setprecision(4) << score.sequence << ": S@5 " << score.errors.success_5
                    << " under its floor " << l.success_5 << "; E_AL >= 5 px on "
                    << frames_at_or_over(frame_errors(frames_csv, "bdsp", score.sequence), 5.0);
    }
    // A failure (no scorable boundary) counts against S@10 and S@5; the mean is over the rest.
    if (!(score.errors.mean <= l.mean)) {
      ADD_FAILURE() << std::setprecision(4) << score.sequence << ": mean E_AL " << score.errors.mean
                    << " px over its ceiling " << l.mean << " px; E_AL >= 5 px on "
                    << frames_at_or_over(frame_errors(frames_csv, "bdsp", score.sequence), 5.0);
    }
  }
  EXPECT_EQ(checked, static_cast<int>(limits().size())) << "sequences missing from the dataset";
  std::error_code ignored;
  std::filesystem::remove_all(options.out, ignored);
}

}  // namespace
}  // namespace scbt
