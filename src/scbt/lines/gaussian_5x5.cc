#include "scbt/lines/gaussian_5x5.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "scbt/lines/pixel_loop.h"

namespace scbt {
namespace {

// The kernel OpenCV derives for size 5 and sigma 1 in 8-bit fixed point (sums to 256); the
// test against cv::GaussianBlur pins it.
constexpr int kOuter = 14, kInner = 62, kCentre = 104;

// BORDER_REFLECT_101: ... 2 1 | 0 1 2 ... n-1 | n-2 ...
int reflect_101(int i, int n) {
  if (n == 1) return 0;
  while (i < 0 || i >= n) i = i < 0 ? -i : 2 * n - 2 - i;
  return i;
}

// One row filtered horizontally, kept exact: at most 255 * 256, so 16 bits suffice.
SCBT_PIXEL_LOOP void horizontal_pass(const std::uint8_t* __restrict x, std::uint16_t* __restrict h,
                                     int w) {
  for (int c = 2; c < w - 2; ++c) {
    h[c] = static_cast<std::uint16_t>(kOuter * (x[c - 2] + x[c + 2]) +
                                      kInner * (x[c - 1] + x[c + 1]) + kCentre * x[c]);
  }
  for (int c = 0; c < std::min(w, 2); ++c) {  // the reflected borders
    for (const int at : {c, w - 1 - c}) {
      h[at] = static_cast<std::uint16_t>(
          kOuter * (x[reflect_101(at - 2, w)] + x[reflect_101(at + 2, w)]) +
          kInner * (x[reflect_101(at - 1, w)] + x[reflect_101(at + 1, w)]) + kCentre * x[at]);
    }
  }
}

// Five horizontally filtered rows into one output row: the exact sum needs 24 bits, then one
// rounding to 8 bits.
SCBT_PIXEL_LOOP void vertical_pass(const std::uint16_t* __restrict a,
                                   const std::uint16_t* __restrict b,
                                   const std::uint16_t* __restrict c,
                                   const std::uint16_t* __restrict d,
                                   const std::uint16_t* __restrict e, std::uint8_t* __restrict out,
                                   int w) {
  for (int i = 0; i < w; ++i) {
    const std::uint32_t sum = kOuter * (std::uint32_t{a[i]} + e[i]) +
                              kInner * (std::uint32_t{b[i]} + d[i]) + kCentre * std::uint32_t{c[i]};
    out[i] = static_cast<std::uint8_t>((sum + (1u << 15)) >> 16);
  }
}

}  // namespace

void gaussian_blur_5x5(const cv::Mat& gray, cv::Mat* out) {
  if (gray.type() != CV_8UC1) {
    throw std::invalid_argument("gaussian_blur_5x5 needs an 8-bit single-channel image, got type " +
                                std::to_string(gray.type()));
  }
  out->create(gray.size(), CV_8UC1);
  const int w = gray.cols, h = gray.rows;
  if (w == 0 || h == 0) return;
  // Horizontally filtered rows in a ring of five (row q in slot q % 5): every output row reads
  // rows within two of it (reflected at the ends), all among the last five filtered.
  thread_local std::vector<std::uint16_t> ring;
  ring.resize(static_cast<size_t>(5) * w);
  int filtered = -1;  // the last row filtered horizontally
  for (int r = 0; r < h; ++r) {
    for (const int last = std::min(r + 2, h - 1); filtered < last;) {
      ++filtered;
      horizontal_pass(gray.ptr<std::uint8_t>(filtered),
                      ring.data() + static_cast<size_t>(filtered % 5) * w, w);
    }
    const std::uint16_t* rows[5];
    for (int k = 0; k < 5; ++k) {
      rows[k] = ring.data() + static_cast<size_t>(reflect_101(r + k - 2, h) % 5) * w;
    }
    vertical_pass(rows[0], rows[1], rows[2], rows[3], rows[4], out->ptr<std::uint8_t>(r), w);
  }
}

}  // namespace scbt
