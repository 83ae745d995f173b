// SIGINT / SIGTERM / SIGHUP as a request to stop a run after the current frame (`scbt track`
// then commits complete outputs for the frames tracked so far).
#pragma once

#include <signal.h>

namespace scbt {

// Installs a handler for SIGINT, SIGTERM and SIGHUP (a closed terminal) for its lifetime -- each
// unless the process ignores it already (nohup, a background job), which stays ignored -- and
// ignores SIGPIPE, so that a reader of standard output going away shows as EPIPE
// (OutputSet::reader_gone) and ends the run cleanly; then restores the old handlers. Disabled,
// it installs nothing and stop_signal() stays 0.
class StopSignalScope {
 public:
  explicit StopSignalScope(bool enabled);
  ~StopSignalScope();
  StopSignalScope(const StopSignalScope&) = delete;
  StopSignalScope& operator=(const StopSignalScope&) = delete;

  // The signal received since the scope began, else 0. A handled signal also stops any bounded
  // read in progress (scbt/io/bounded_read.h: request_stop).
  int stop_signal() const;

 private:
  bool enabled_;
  struct sigaction old_int_ {};
  struct sigaction old_term_ {};
  struct sigaction old_hup_ {};
  struct sigaction old_pipe_ {};
};

}  // namespace scbt
