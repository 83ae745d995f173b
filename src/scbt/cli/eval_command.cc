#include <iostream>

#include "scbt/app/eval_run.h"
#include "scbt/app/gap_eval_run.h"
#include "scbt/app/perturbed_eval_run.h"
#include "scbt/cli/commands.h"
#include "scbt/eval/dataset.h"
#include "scbt/io/frame_source.h"
#include "scbt/peers/polygon_tracker.h"

namespace scbt::cli {
namespace {

// `scbt eval --list`: what the dataset and the tracker factory offer.
void list_dataset(const EvalRunOptions& options) {
  std::cout << "trackers:";
  for (const std::string& name : polygon_tracker_names()) std::cout << ' ' << name;
  std::cout << '\n';
  if (options.dataset.empty()) return;
  std::cout << "sequences of " << options.dataset << ":\n";
  for (const DatasetSequence& s : list_dataset_sequences(options.dataset)) {
    std::cout << "  " << s.name << "  (" << open_frame_source(s.frames)->frame_count()
              << " frames)\n";
  }
}

}  // namespace

void add_eval_command(CLI::App& app, int* exit_code) {
  auto options = std::make_shared<EvalRunOptions>();
  auto list = std::make_shared<bool>(false);
  auto no_plot = std::make_shared<bool>(false);
  auto perturb = std::make_shared<std::string>();
  auto perturb_seed = std::make_shared<unsigned long long>(1);
  auto gaps = std::make_shared<bool>(false);
  auto gap_at = std::make_shared<std::vector<double>>();
  CLI::App* command = app.add_subcommand(
      "eval",
      "Run trackers over a dataset laid out like the public one (or score existing results) "
      "and report E_AL success rates, AUC and timings, with success-curve plots");
  command->add_option("--dataset", options->dataset,
                      "Dataset folder: OriginalVideosAVI/<Seq>/NNNN.jpg and "
                      "GroundTruthByPolygons/<Seq>_TrackingGroundTruth.txt");
  command
      ->add_option("--sequences", options->sequences,
                   "Sequences to use, comma separated (default: all)")
      ->delimiter(',');
  command
      ->add_option("--trackers", options->trackers,
                   "Trackers to run, comma separated (default: all, or none with --results)")
      ->delimiter(',');
  command->add_option("--results", options->results,
                      "Score existing results: NAME=DIR with DIR/<Seq>.txt (one polygon line per "
                      "frame); repeatable. Nothing is run unless --trackers is also given");
  command->add_option("--out", options->out,
                      "Output folder: <tracker>/<Seq>.txt, report.md (with the confidence's ROC "
                      "AUC per sequence), summary.csv, frames.csv, curves.csv, loss.csv, "
                      "success_curves.png");
  command->add_option("-j,--jobs", options->jobs, "Parallel jobs (0: one per core)")
      ->capture_default_str();
  command->add_option("--max-frames", options->max_frames,
                      "Only the first N frames of each sequence (0: all)");
  command->add_option(
      "--perturb", *perturb,
      "Evaluate once per perturbation of the frames, separated by ';' or spaces, each into "
      "OUT/<spec>/, plus OUT/perturb_summary.md/.csv and perturb_levels.png: none, stride:K, "
      "noise:SIGMA, blur:SIGMA, motion-blur:LENGTH[,DEGREES], brightness:B, contrast:C, gamma:G, "
      "lowlight:B[,SIGMA], jpeg:QUALITY, downscale:FACTOR (docs/robustness-to-camera.md), "
      "occlude:COVER[,SECONDS[,bar|disc|hand[,sweep|stay[,solid|textured]]]] (occluders hiding "
      "COVER of the outline at several seeded places of each sequence; where they were is "
      "written to OUT/<spec>/<tracker>/<Seq>.occlusion.txt, bench/occlusion_report.py scores "
      "them)");
  command
      ->add_option("--perturb-seed", *perturb_seed,
                   "Seed of the perturbations' noise and of the occluders' places")
      ->capture_default_str();
  command->add_flag(
      "--gaps", *gaps,
      "Also evaluate gap variants of every sequence, from its middle: 30 frames replaced by "
      "uniform grey, 60 frames dropped (a 2 s jump); into OUT/clean, OUT/grey30, OUT/jump60, plus "
      "OUT/gaps_summary.md/.csv: confidence ROC AUC, re-acquisition delay, S@10 after it "
      "(docs/loss-handling.md)");
  command
      ->add_option("--gap-at", *gap_at,
                   "With --gaps: where the gaps start, as fractions of each sequence, comma "
                   "separated (default 0.5); each variant is run at each, into OUT/grey30@F and "
                   "OUT/jump60@F")
      ->delimiter(',');
  command->add_flag("--no-plot", *no_plot, "Do not write success_curves.png");
  command->add_flag("-q,--quiet", options->quiet, "No progress output");
  command->add_flag("--list", *list, "List the trackers and the dataset's sequences, then exit");
  // -o is `track`'s results file; this command writes a folder.
  command->add_option("-o")->group("")->each([](const std::string&) {
    throw std::invalid_argument(
        "eval writes a folder: give it as --out DIR (-o is track's results file)");
  });
  auto flags = add_tracker_options(command);
  command->callback([options, flags, list, no_plot, perturb, perturb_seed, gaps, gap_at,
                     exit_code] {
    if (flags->apply(&options->tracker)) {
      *exit_code = kExitOk;
      return;
    }
    if (*list) {
      list_dataset(*options);
      *exit_code = 0;
      return;
    }
    options->plot = !*no_plot;
    if (!gap_at->empty() && !*gaps) throw std::invalid_argument("--gap-at needs --gaps");
    if (*gaps) {
      if (!perturb->empty())
        throw std::invalid_argument("--gaps cannot be combined with --perturb");
      const GapEvalSummary summary =
          run_gap_evals(*options, std::cerr, gap_at->empty() ? std::vector<double>{0.5} : *gap_at);
      if (!options->quiet) std::cout << summary.files.front() << '\n';
      *exit_code = 0;
      return;
    }
    if (!perturb->empty()) {
      const PerturbedEvalSummary summary = run_perturbed_evals(
          *options, parse_perturbation_list(*perturb, *perturb_seed), std::cerr);
      if (!options->quiet) std::cout << summary.files.front() << '\n';
      *exit_code = 0;
      return;
    }
    const EvalRunSummary summary = run_eval(*options, std::cerr);
    if (!options->quiet) std::cout << summary.files.front() << '\n';
    *exit_code = 0;
  });
}

}  // namespace scbt::cli
