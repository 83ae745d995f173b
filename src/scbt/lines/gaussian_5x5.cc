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

// The weights as values the compiler cannot see, for the vectorised passes: it would otherwise
// turn each product by a constant into shifts and adds (11 instructions for the three weights),
// where one 16-bit multiply each is cheaper (whole 360x300 blur: 38.4 -> 31.0 us).
struct Weights {
  int outer = kOuter, inner = kInner, centre = kCentre;
  Weights() {
#if defined(__GNUC__)
    asm("" : "+r"(outer), "+r"(inner), "+r"(centre));
#endif
  }
};

// BORDER_REFLECT_101: ... 2 1 | 0 1 2 ... n-1 | n-2 ...
int reflect_101(int i, int n) {
  if (i >= 0 && i < n) return i;
  if (n == 1) return 0;
  while (i < 0 || i >= n) i = i < 0 ? -i : 2 * n - 2 - i;
  return i;
}

// Columns from .. to - 1 (all at least 2 from the row's ends) of one row filtered horizontally,
// kept exact: at most 255 * 256, so 16 bits suffice.
SCBT_PIXEL_LOOP void horizontal_interior(const std::uint8_t* __restrict x,
                                         std::uint16_t* __restrict h, int from, int to) {
  const Weights weights;
  const int outer = weights.outer, inner = weights.inner, centre = weights.centre;
  for_each_pixel(from, to, [=](int c) {
    h[c] = static_cast<std::uint16_t>(outer * (x[c - 2] + x[c + 2]) +
                                      inner * (x[c - 1] + x[c + 1]) + centre * x[c]);
  });
}

// Column c of a row of width w filtered horizontally, its neighbours reflected at the ends.
std::uint16_t horizontal_reflected(const std::uint8_t* x, int c, int w) {
  return static_cast<std::uint16_t>(kOuter * (x[reflect_101(c - 2, w)] + x[reflect_101(c + 2, w)]) +
                                    kInner * (x[reflect_101(c - 1, w)] + x[reflect_101(c + 1, w)]) +
                                    kCentre * x[c]);
}

// Columns from .. to - 1 of one row filtered horizontally.
void horizontal_pass(const std::uint8_t* x, std::uint16_t* h, int w, int from, int to) {
  horizontal_interior(x, h, std::max(from, 2), std::min(to, w - 2));
  for (int c = from; c < std::min(to, 2); ++c) h[c] = horizontal_reflected(x, c, w);
  for (int c = std::max(from, std::max(w - 2, 2)); c < to; ++c) {
    h[c] = horizontal_reflected(x, c, w);
  }
}

// Five horizontally filtered rows into one output row: the weighted sum S = 256 A + B needs 24
// bits, but its rounding to 8 bits, (S + 2^15) >> 16, equals (A + (B >> 8) + 128) >> 8 where A
// and B are the weighted sums of the rows' high and low bytes (floor((n + t) / k) = floor((n +
// floor(t)) / k) for integer n); A, B and A + (B >> 8) + 128 < 2^16 (the result is at most 255),
// so the whole pass runs in 16-bit lanes, twice as many per vector as 32-bit sums.
SCBT_PIXEL_LOOP void vertical_pass(const std::uint16_t* __restrict a,
                                   const std::uint16_t* __restrict b,
                                   const std::uint16_t* __restrict c,
                                   const std::uint16_t* __restrict d,
                                   const std::uint16_t* __restrict e, std::uint8_t* __restrict out,
                                   int w) {
  const Weights weights;
  const int outer = weights.outer, inner = weights.inner, centre = weights.centre;
  for_each_pixel(0, w, [=](int i) {
    const std::uint16_t high =
        static_cast<std::uint16_t>(outer * ((a[i] >> 8) + (e[i] >> 8)) +
                                   inner * ((b[i] >> 8) + (d[i] >> 8)) + centre * (c[i] >> 8));
    const std::uint16_t low = static_cast<std::uint16_t>(outer * ((a[i] & 0xFF) + (e[i] & 0xFF)) +
                                                         inner * ((b[i] & 0xFF) + (d[i] & 0xFF)) +
                                                         centre * (c[i] & 0xFF));
    const std::uint16_t rounded = static_cast<std::uint16_t>(high + (low >> 8) + 128);
    out[i] = static_cast<std::uint8_t>(rounded >> 8);
  });
}

}  // namespace

namespace {

void check_type(const cv::Mat& gray) {
  if (gray.type() != CV_8UC1) {
    throw std::invalid_argument("gaussian_blur_5x5 needs an 8-bit single-channel image, got type " +
                                std::to_string(gray.type()));
  }
}

// Horizontally filtered rows in a ring of five (row q in slot q % 5): every output row reads
// rows within two of it (reflected at the ends), all among the last five filtered.
// for_each_span(row, f) calls f(from, to) for each column range of `row` to compute.
template <typename ForEachSpan>
void blur(const cv::Mat& gray, cv::Mat* out, const ForEachSpan& for_each_span) {
  const int w = gray.cols, h = gray.rows;
  if (w == 0 || h == 0) return;
  thread_local std::vector<std::uint16_t> ring;
  ring.resize(static_cast<size_t>(5) * w);
  int filtered = -1;  // the last row filtered horizontally
  for (int r = 0; r < h; ++r) {
    for (const int last = std::min(r + 2, h - 1); filtered < last;) {
      ++filtered;
      const std::uint8_t* x = gray.ptr<std::uint8_t>(filtered);
      std::uint16_t* slot = ring.data() + static_cast<size_t>(filtered % 5) * w;
      for_each_span(filtered, [&](int from, int to) { horizontal_pass(x, slot, w, from, to); });
    }
    const std::uint16_t* rows[5];
    for (int k = 0; k < 5; ++k) {
      rows[k] = ring.data() + static_cast<size_t>(reflect_101(r + k - 2, h) % 5) * w;
    }
    std::uint8_t* y = out->ptr<std::uint8_t>(r);
    for_each_span(r, [&](int from, int to) {
      vertical_pass(rows[0] + from, rows[1] + from, rows[2] + from, rows[3] + from, rows[4] + from,
                    y + from, to - from);
    });
  }
}

}  // namespace

void gaussian_blur_5x5(const cv::Mat& gray, cv::Mat* out) {
  check_type(gray);
  out->create(gray.size(), CV_8UC1);
  const int w = gray.cols;
  blur(gray, out, [w](int, const auto& f) { f(0, w); });
}

void gaussian_blur_5x5(const cv::Mat& gray, const RowSpans& where, cv::Mat* out) {
  check_type(gray);
  if (where.size() != gray.size()) {
    throw std::invalid_argument("gaussian_blur_5x5: the spans' window differs from the image's");
  }
  out->create(gray.size(), CV_8UC1);
  blur(gray, out, [&where](int row, const auto& f) {
    for (const ColumnSpan* s = where.begin(row); s != where.end(row); ++s) f(s->begin, s->end);
  });
}

}  // namespace scbt
