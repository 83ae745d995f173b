#include "scbt/app/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iostream>

namespace scbt {
namespace {

constexpr int kFramesPerLine = 500;  // the step of a plain progress line when the total is unknown

bool is_terminal(const std::ostream& out) {
  if (&out == &std::cerr || &out == &std::clog) return ::isatty(STDERR_FILENO) == 1;
  if (&out == &std::cout) return ::isatty(STDOUT_FILENO) == 1;
  return false;
}

}  // namespace

ProgressBar::ProgressBar(std::ostream& out, std::string label, int total, bool enabled)
    : out_(out),
      label_(std::move(label)),
      total_(total),
      enabled_(enabled),
      terminal_(is_terminal(out)),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_ - std::chrono::seconds(1)) {}

void ProgressBar::update(int done, const std::string& note) {
  if (!enabled_) return;
  if (!terminal_) {
    const int step = total_ > 0 ? static_cast<int>(10LL * std::min(done, total_) / total_)
                                : done / kFramesPerLine;
    if (step > reported_step_ && (total_ <= 0 || done < total_)) {
      reported_step_ = step;
      write_line(done, note);
    }
    return;
  }
  const auto now = std::chrono::steady_clock::now();
  if (now - last_draw_ < std::chrono::milliseconds(200)) return;
  last_draw_ = now;
  draw(done, note);
}

void ProgressBar::finish(int done, const std::string& note) {
  if (!enabled_) return;
  if (!terminal_) {
    write_line(done, note);
    return;
  }
  draw(done, note);
  out_ << '\n' << std::flush;
  line_open_ = false;
}

void ProgressBar::break_line() {
  if (!line_open_) return;
  out_ << '\n' << std::flush;
  line_open_ = false;
}

void ProgressBar::write_line(int done, const std::string& note) {
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  char line[256];
  if (total_ > 0) {
    std::snprintf(line, sizeof(line), "%s: %d/%d frames (%.0f%%) %.1fs%s%s\n", label_.c_str(), done,
                  total_, 100.0 * std::min(1.0, static_cast<double>(done) / total_), seconds,
                  note.empty() ? "" : " ", note.c_str());
  } else {
    std::snprintf(line, sizeof(line), "%s: %d frames %.1fs%s%s\n", label_.c_str(), done, seconds,
                  note.empty() ? "" : " ", note.c_str());
  }
  out_ << line << std::flush;
}

void ProgressBar::draw(int done, const std::string& note) {
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  char line[256];
  if (total_ > 0) {
    constexpr int kWidth = 30;
    const double fraction = std::min(1.0, static_cast<double>(done) / total_);
    const int filled = static_cast<int>(fraction * kWidth);
    std::string bar(filled, '#');
    bar.resize(kWidth, '.');
    std::snprintf(line, sizeof(line), "\r%s [%s] %d/%d %5.1f%% %.1fs %s", label_.c_str(),
                  bar.c_str(), done, total_, 100.0 * fraction, seconds, note.c_str());
  } else {
    std::snprintf(line, sizeof(line), "\r%s %d frames %.1fs %s", label_.c_str(), done, seconds,
                  note.c_str());
  }
  out_ << line << std::flush;
  line_open_ = true;
}

}  // namespace scbt
