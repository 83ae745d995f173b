// A one-line progress bar on a terminal stream, redrawn at most a few times per second.
#pragma once

#include <chrono>
#include <ostream>
#include <string>

namespace scbt {

class ProgressBar {
 public:
  // total <= 0 shows a counter without a bar. Nothing is drawn when `enabled` is false.
  ProgressBar(std::ostream& out, std::string label, int total, bool enabled);
  void update(int done, const std::string& note = "");
  // Draws the final state and ends the line.
  void finish(int done, const std::string& note = "");

 private:
  void draw(int done, const std::string& note);
  std::ostream& out_;
  std::string label_;
  int total_;
  bool enabled_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace scbt
