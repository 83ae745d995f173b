// The clock the tracker's stage timings (TrackResult's *_ms) are read with.
#pragma once

#include <chrono>

namespace scbt {

using Clock = std::chrono::steady_clock;

// Milliseconds since `since`.
inline double elapsed_ms(Clock::time_point since) {
  return std::chrono::duration<double, std::milli>(Clock::now() - since).count();
}

}  // namespace scbt
