// scbt: the command-line front end. Each subcommand only declares its options and calls the
// library function that does the work (src/scbt/app), so tests can call the same code.
#include <fcntl.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <csignal>
#include <exception>
#include <iostream>

#include "scbt/cli/commands.h"
#include "scbt/io/bounded_read.h"
#include "scbt/version.h"

namespace {

// A descriptor among 0-2 that the parent closed (`2>&-`) would be the next one open() returns:
// a results file would take over standard error and receive the progress bar. /dev/null is
// opened onto each closed one first, so outputs always get descriptors above 2.
void open_null_onto_closed_standard_fds() {
  for (int fd = 0; fd <= 2; ++fd) {
    if (::fcntl(fd, F_GETFD) != -1 || errno != EBADF) continue;
    const int opened = ::open("/dev/null", fd == 0 ? O_RDONLY : O_WRONLY);
    if (opened < 0) _exit(scbt::cli::kExitFailure);  // no way to report it, nor to run safely
    if (opened != fd) {  // cannot happen: the lowest free descriptor is fd
      ::dup2(opened, fd);
      ::close(opened);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  open_null_onto_closed_standard_fds();
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
  } catch (const scbt::Interrupted& e) {
    // Stopped by a signal before the first frame (waiting on a FIFO, reading an endless file).
    return scbt::cli::report_error(e.what(), scbt::cli::kExitInterrupted + e.signal_number());
  } catch (const std::invalid_argument& e) {
    return scbt::cli::report_error(e.what(), scbt::cli::kExitUsage);
  } catch (const std::exception& e) {
    return scbt::cli::report_error(e.what(), scbt::cli::kExitFailure);
  }
  return exit_code;
}
