#include "scbt/app/progress.h"

#include <cstdio>

namespace scbt {

ProgressBar::ProgressBar(std::ostream& out, std::string label, int total, bool enabled)
    : out_(out),
      label_(std::move(label)),
      total_(total),
      enabled_(enabled),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_ - std::chrono::seconds(1)) {}

void ProgressBar::update(int done, const std::string& note) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_draw_ < std::chrono::milliseconds(200)) return;
  last_draw_ = now;
  draw(done, note);
}

void ProgressBar::finish(int done, const std::string& note) {
  if (!enabled_) return;
  draw(done, note);
  out_ << '\n' << std::flush;
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
}

}  // namespace scbt
