// Log lines limited per reason rather than per call site: a reason logged within the last
// `period` seconds is not logged again, while a different one is logged at once (a second bad
// image, another encoding, another error from the tracker). At most `max_reasons` reasons are
// remembered at a time; beyond them a new reason waits until one has aged out, so that a
// stream of ever-different errors still gives at most that many lines per period.
#pragma once

#include <cstddef>
#include <iterator>
#include <mutex>
#include <string>
#include <unordered_map>

namespace scbt::ros_node {

class ReasonThrottle {
 public:
  explicit ReasonThrottle(double period_s = 5.0, std::size_t max_reasons = 64)
      : period_(period_s), max_reasons_(max_reasons) {}

  // True when `reason` may be logged at `now_s` (seconds, any monotonic clock); it then counts as
  // logged at that time. Thread-safe.
  bool allow(const std::string& reason, double now_s) {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto found = last_.find(reason);
    if (found != last_.end()) {
      if (now_s - found->second < period_) return false;
      found->second = now_s;
      return true;
    }
    if (last_.size() >= max_reasons_) {
      for (auto it = last_.begin(); it != last_.end();)
        it = now_s - it->second >= period_ ? last_.erase(it) : std::next(it);
      if (last_.size() >= max_reasons_) return false;
    }
    last_.emplace(reason, now_s);
    return true;
  }

 private:
  std::mutex mutex_;
  double period_;
  std::size_t max_reasons_;
  std::unordered_map<std::string, double> last_;
};

}  // namespace scbt::ros_node
