// The outputs of `scbt eval` from its jobs' outcomes: scores per (tracker, sequence) and pooled,
// frames.csv, summary.csv, curves.csv, loss.csv, success_curves.png and report.md.
#pragma once

#include <string>
#include <vector>

#include "scbt/app/eval_jobs.h"

namespace scbt {

// What run_eval knows about the run, for the report's notes.
struct EvalRunContext {
  std::vector<EvalSequence> sequences;
  std::vector<std::string> trackers;                         // run
  std::vector<std::pair<std::string, std::string>> results;  // scored: name, folder
  std::vector<EvalJob> jobs;
  std::vector<EvalJobOutcome> outcomes;
  int threads = 0;
};

// Fills summary->scores, ->loss and ->warnings and writes every output into options.out (each
// atomically; report.md first in summary->files). Returns the failed jobs ("tracker/seq: error").
std::vector<std::string> write_eval_outputs(const EvalRunOptions& options,
                                            const EvalRunContext& run, EvalRunSummary* summary,
                                            EvalClock::time_point start);

}  // namespace scbt
