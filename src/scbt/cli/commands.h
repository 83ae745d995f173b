// Subcommand registration. Each command lives in its own file; its add_* function declares the
// options on the CLI11 app and a callback that runs the work and stores the exit code.
#pragma once

#include <CLI/CLI.hpp>
#include <map>
#include <memory>
#include <string>

#include "scbt/app/track_run.h"
#include "scbt/tracker/tracker_options.h"

namespace scbt::cli {

// Exit codes of every command (documented in the README):
constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;    // bad input data, unreadable input, unwritable output
constexpr int kExitUsage = 2;      // bad command line: unknown option, value out of range
constexpr int kExitBadFrames = 3;  // finished, but some frames were bad and held
// + signal number: stopped by SIGHUP (129), SIGINT (130), SIGTERM (143), or by the reader of a
// streamed output going away (EPIPE: 141, as SIGPIPE).
constexpr int kExitInterrupted = 128;

// Prints "scbt: error: MESSAGE" as one line on stderr and returns `exit_code`.
int report_error(const std::string& message, int exit_code);

void add_track_command(CLI::App& app, int* exit_code);

// The live/interactive window mode of `scbt track` (live_command.cc).
struct LiveOptions {
  int camera = -1;  // --camera N
  bool interactive = false;
  std::string save_input;
  double playback_fps = 0.0;
};
std::shared_ptr<LiveOptions> add_live_options(CLI::App* command);
// Runs the interactive session when --camera or --interactive was given (returns true), else
// returns false so that the batch run goes on. Throws std::invalid_argument on bad combinations.
bool run_live_if_requested(const LiveOptions& live, const TrackRunOptions& track, int* exit_code);
void add_demo_command(CLI::App& app, int* exit_code);
void add_eval_command(CLI::App& app, int* exit_code);
void add_bench_command(CLI::App& app, int* exit_code);

// The tracker options shared by every command that tracks: --config FILE and one flag per option
// of the option table (--detector, --filter-distance, ...). CLI11 fills them while parsing; apply()
// then sets the config file's options, then the flags given, and checks the result (throws
// std::invalid_argument with the table's message); with --print-config it prints them (YAML) and
// returns true: the command then stops.
struct TrackerOptionFlags {
  struct Flag {
    std::string text;
    CLI::Option* option = nullptr;
  };
  std::string config;
  bool print_config = false;
  std::map<std::string, Flag> flags;  // by option name

  bool apply(TrackerOptions* options) const;
};
std::shared_ptr<TrackerOptionFlags> add_tracker_options(CLI::App* command);

}  // namespace scbt::cli
