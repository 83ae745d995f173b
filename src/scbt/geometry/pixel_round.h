// A sample point's pixel: the nearest one, rounded as std::lround rounds but inline (the library's
// is a call, and the tracker rounds a few hundred points per frame).
#pragma once

#include <cmath>

namespace scbt {

// static_cast<int>(std::lround(x)): halves away from zero.
inline int round_to_pixel(double x) {
  if (!(std::abs(x) < 2147483647.0)) return static_cast<int>(std::lround(x));  // NaN, huge
  const int whole = static_cast<int>(x);                                       // towards zero
  const double rest = x - whole;  // exact: x and whole share their leading bits
  return whole + (rest >= 0.5) - (rest <= -0.5);
}

}  // namespace scbt
