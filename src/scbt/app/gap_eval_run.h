// `scbt eval --gaps`: the evaluation of every sequence as it is and in two gap variants (30
// frames replaced by uniform grey, 60 frames dropped; eval/sequence_gap.h), each in its own
// folder with the usual report, then one table of the confidence's ROC AUC, the re-acquisition
// delays and the success after re-acquisition per sequence.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "scbt/app/eval_run.h"

namespace scbt {

struct GapEvalRun {
  // clean, grey30, jump60 (a gap from the middle) or grey30@0.2 (from 20 % of each sequence):
  // also the folder OUT/<variant>
  std::string variant;
  EvalRunSummary summary;
};

struct GapEvalSummary {
  std::vector<GapEvalRun> runs;
  std::vector<std::string> files;  // gaps_summary.md first, then gaps_summary.csv
};

// Runs `base` (its gap ignored) as it is and with each gap variant at each of `positions`
// (fractions of each sequence) into OUT/<variant>, then writes OUT/gaps_summary.md and
// OUT/gaps_summary.csv. Throws like run_eval.
GapEvalSummary run_gap_evals(const EvalRunOptions& base, std::ostream& log,
                             const std::vector<double>& positions = {0.5});

}  // namespace scbt
