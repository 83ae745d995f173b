// Subcommand registration. Each command lives in its own file; its add_* function declares the
// options on the CLI11 app and a callback that runs the work and stores the exit code.
#pragma once

#include <CLI/CLI.hpp>

#include "scbt/tracker/tracker_options.h"

namespace scbt::cli {

void add_track_command(CLI::App& app, int* exit_code);
void add_demo_command(CLI::App& app, int* exit_code);
void add_eval_command(CLI::App& app, int* exit_code);

// The tracker options shared by every command that tracks (--detector, --filter-distance, ...).
void add_tracker_options(CLI::App* command, TrackerOptions* options, std::string* detector_name);

}  // namespace scbt::cli
