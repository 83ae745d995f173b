#include "scbt/app/stop_signal.h"

#include <csignal>

#include "scbt/io/bounded_read.h"

namespace scbt {
namespace {

// Records the request (read once per frame by the run, and by every bounded read).
extern "C" void on_stop_signal(int signal_number) { request_stop(signal_number); }

// Catches `signal_number` unless it is ignored already: a signal ignored by the parent (nohup
// for SIGHUP, a shell's background job for SIGINT) stays ignored, as shells expect. Without
// SA_RESTART, so that a wait in open() or read() (a FIFO) ends with EINTR and the run can stop.
void catch_unless_ignored(int signal_number, struct sigaction* old) {
  sigaction(signal_number, nullptr, old);
  if (old->sa_handler == SIG_IGN) return;
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  sigaction(signal_number, &action, nullptr);
}

}  // namespace

StopSignalScope::StopSignalScope(bool enabled) : enabled_(enabled) {
  clear_stop_request();
  if (!enabled_) return;
  catch_unless_ignored(SIGINT, &old_int_);
  catch_unless_ignored(SIGTERM, &old_term_);
  catch_unless_ignored(SIGHUP, &old_hup_);
  struct sigaction ignore {};
  ignore.sa_handler = SIG_IGN;
  sigemptyset(&ignore.sa_mask);
  sigaction(SIGPIPE, &ignore, &old_pipe_);
}

StopSignalScope::~StopSignalScope() {
  if (enabled_) {
    sigaction(SIGINT, &old_int_, nullptr);
    sigaction(SIGTERM, &old_term_, nullptr);
    sigaction(SIGHUP, &old_hup_, nullptr);
    sigaction(SIGPIPE, &old_pipe_, nullptr);
  }
  // A request seen by this run is not one for later reads of the process.
  clear_stop_request();
}

int StopSignalScope::stop_signal() const { return enabled_ ? stop_requested() : 0; }

}  // namespace scbt
