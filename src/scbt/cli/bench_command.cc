#include <iostream>

#include "scbt/app/bench_run.h"
#include "scbt/cli/commands.h"

namespace scbt::cli {

void add_bench_command(CLI::App& app, int* exit_code) {
  auto options = std::make_shared<BenchRunOptions>();
  auto full_frame = std::make_shared<bool>(false);
  auto no_compare = std::make_shared<bool>(false);
  CLI::App* command = app.add_subcommand(
      "bench",
      "Time every stage per sequence (median/p90/p99, fps, peak RSS) and the speed-up against "
      "the straightforward configuration (whole-frame detection, generic graph) measured in the "
      "same run; run it pinned: taskset -c 0 scbt bench");
  command->add_option("--dataset", options->dataset, "Dataset folder")->required();
  command->add_option("--sequences", options->sequences, "Only these sequences (default: all)");
  command->add_option("--max-frames", options->max_frames,
                      "Frames per sequence, the initial one included (0: all)");
  command->add_option("--csv", options->csv, "Write the per-sequence figures as CSV");
  command->add_flag("--full-frame", *full_frame,
                    "Detect lines on the whole frame in the configuration under test too");
  command->add_flag("--no-compare", *no_compare,
                    "Skip the straightforward (whole-frame, generic-graph) configuration");
  command
      ->add_option("--roi-padding", options->tracker.detector.roi_padding,
                   "Pixels added around the filter band of the detection window")
      ->capture_default_str();
  command->add_flag("-q,--quiet", options->quiet, "No progress bars");
  auto flags = add_tracker_options(command);
  command->callback([options, flags, full_frame, no_compare, exit_code] {
    if (flags->apply(&options->tracker)) {
      *exit_code = kExitOk;
      return;
    }
    options->tracker.detector.crop_to_boundary = !*full_frame;
    options->compare = !*no_compare;
    const BenchReport report = run_bench(*options, std::cerr);
    std::cout << format_bench_report(report) << std::flush;
    *exit_code = 0;
  });
}

}  // namespace scbt::cli
