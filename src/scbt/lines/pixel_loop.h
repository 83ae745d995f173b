// SCBT_PIXEL_LOOP marks a function whose loops run over every pixel of a window: compiled also
// for AVX2 where the CPU has it (avx2_clones.h), so that its 8- and 16-bit arithmetic vectorises
// twice as wide.
#pragma once

#include "scbt/geometry/avx2_clones.h"

#define SCBT_PIXEL_LOOP SCBT_AVX2_CLONES

namespace scbt {

// The pixels a vectorised row loop takes at a time (32 lanes of 8 bits with AVX2).
constexpr int kPixelChunk = 32;

// Calls pixel(c) for each column c in [from, to), in chunks of kPixelChunk columns: a loop of
// constant count, which the compiler vectorises whole. A range that is not a whole number of
// chunks ends with a chunk moved back to end at `to` (recomputing a few columns) instead of a
// pixel-by-pixel remainder, which the tracker's short band spans would otherwise pay on every
// row. So pixel(c) must compute column c from inputs it does not write. Ranges shorter than a
// chunk go pixel by pixel.
template <typename Pixel>
inline __attribute__((always_inline)) void for_each_pixel(int from, int to, const Pixel& pixel) {
  if (to - from < kPixelChunk) {
    for (int c = from; c < to; ++c) pixel(c);
    return;
  }
  int c = from;
  for (; c + kPixelChunk <= to; c += kPixelChunk) {
    for (int k = 0; k < kPixelChunk; ++k) pixel(c + k);
  }
  if (c < to) {
    c = to - kPixelChunk;
    for (int k = 0; k < kPixelChunk; ++k) pixel(c + k);
  }
}

}  // namespace scbt
