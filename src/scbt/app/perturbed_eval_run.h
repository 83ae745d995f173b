// `scbt eval --perturb LIST`: the evaluation repeated once per perturbation of the frames
// (eval/perturb.h), each in its own folder with the usual report, then one summary table of the
// success rates per perturbation and a plot of pooled success at 10 px against the level.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "scbt/app/eval_run.h"
#include "scbt/eval/perturb.h"

namespace scbt {

struct PerturbedEvalRun {
  Perturbation perturbation;
  std::string folder;  // OUT/<folder>: that perturbation's eval outputs
  EvalRunSummary summary;
};

struct PerturbedEvalSummary {
  std::vector<PerturbedEvalRun> runs;
  std::vector<std::string> files;  // perturb_summary.md first, then .csv and .png
};

// The folder name of a perturbation's outputs: its spec with ':' and ',' made '_'.
std::string perturbation_folder(const Perturbation& perturbation);

// Runs `base` once per perturbation (its own perturbation ignored) into OUT/<folder>, then writes
// OUT/perturb_summary.md, OUT/perturb_summary.csv and (with base.plot) OUT/perturb_levels.png.
// Throws like run_eval; a failing perturbation stops the rest.
PerturbedEvalSummary run_perturbed_evals(const EvalRunOptions& base,
                                         const std::vector<Perturbation>& perturbations,
                                         std::ostream& log);

}  // namespace scbt
