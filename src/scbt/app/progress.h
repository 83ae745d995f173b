// Progress of a run. On a terminal: a one-line bar redrawn in place ('\r') at most a few times
// per second. Elsewhere (a log file, a pipe): a plain line at every tenth of the total (every 500
// frames when the total is unknown) and at the end, so logs hold no control characters.
#pragma once

#include <chrono>
#include <ostream>
#include <string>

namespace scbt {

class ProgressBar {
 public:
  // total <= 0 shows a counter without a bar. Nothing is drawn when `enabled` is false.
  // `out` is a terminal when it is std::cerr or std::cout and that descriptor is a TTY.
  ProgressBar(std::ostream& out, std::string label, int total, bool enabled);
  void update(int done, const std::string& note = "");
  // Draws the final state and ends the line.
  void finish(int done, const std::string& note = "");
  // Ends the bar's line on a terminal, so that a message can follow on its own line.
  void break_line();
  bool terminal() const { return terminal_; }

 private:
  void draw(int done, const std::string& note);
  void write_line(int done, const std::string& note);
  std::ostream& out_;
  std::string label_;
  int total_;
  bool enabled_;
  bool terminal_;
  bool line_open_ = false;  // a bar is drawn on the terminal's current line
  int reported_step_ = 0;   // the last tenth (or 500-frame step) written as a line
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace scbt
