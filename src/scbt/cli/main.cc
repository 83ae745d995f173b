// scbt: the command-line front end. Each subcommand only declares its options and calls the
// library function that does the work (src/scbt/app), so tests can call the same code.
#include <CLI/CLI.hpp>
#include <csignal>
#include <exception>
#include <iostream>

#include "scbt/cli/commands.h"
#include "scbt/version.h"

int main(int argc, char** argv) {
  // A closed pipe on standard output is EPIPE, not death: `scbt track -o - | head` ends cleanly
  // with its outputs complete (exit code 141, like the shell's for SIGPIPE).
  std::signal(SIGPIPE, SIG_IGN);
  CLI::App app{"scbt: real-time salient closed boundary tracking via line segment grouping"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "scbt " SCBT_VERSION);
  int exit_code = 0;
  scbt::cli::add_track_command(app, &exit_code);
  scbt::cli::add_demo_command(app, &exit_code);
  scbt::cli::add_eval_command(app, &exit_code);
  scbt::cli::add_bench_command(app, &exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    return scbt::cli::report_error(e.what(), scbt::cli::kExitUsage);
  } catch (const std::invalid_argument& e) {
    return scbt::cli::report_error(e.what(), scbt::cli::kExitUsage);
  } catch (const std::exception& e) {
    return scbt::cli::report_error(e.what(), scbt::cli::kExitFailure);
  }
  return exit_code;
}
