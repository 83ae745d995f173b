#include "scbt/motion/block_average.h"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace scbt {
namespace {

// The averaging for factor kFactor, or for the run-time `factor` when kFactor is 0. The factors
// the motion estimate uses are compiled each with its own constant, so that the loops over a block
// unroll and vectorise; their column sums fit 16 bits (8 x 255), twice the lanes of 32.
template <int kFactor>
void average(const cv::Mat& gray, int runtime_factor, cv::Mat* averaged) {
  using Sum = std::conditional_t<(kFactor > 0 && kFactor <= 16), std::uint16_t, std::uint32_t>;
  const int factor = kFactor > 0 ? kFactor : runtime_factor;
  const int width = gray.cols / factor, height = gray.rows / factor;
  averaged->create(height, width, CV_8U);
  int shift = 0;  // log2(factor * factor)
  while ((1 << shift) < factor * factor) ++shift;
  const int half = 1 << (shift - 1);
  const int used = width * factor;
  // Column sums of one band of `factor` rows.
  thread_local std::vector<Sum> columns;
  columns.resize(static_cast<size_t>(used));
  for (int y = 0; y < height; ++y) {
    Sum* __restrict sum = columns.data();
    const std::uint8_t* __restrict first = gray.ptr<std::uint8_t>(y * factor);
    for (int c = 0; c < used; ++c) sum[c] = first[c];
    for (int k = 1; k < factor; ++k) {
      const std::uint8_t* __restrict row = gray.ptr<std::uint8_t>(y * factor + k);
      for (int c = 0; c < used; ++c) sum[c] = static_cast<Sum>(sum[c] + row[c]);
    }
    std::uint8_t* __restrict out = averaged->ptr<std::uint8_t>(y);
    for (int x = 0; x < width; ++x) {
      std::uint32_t block = 0;
      for (int j = 0; j < factor; ++j) block += sum[x * factor + j];
      // Half up for 2 x 2 blocks; half to even otherwise: one more when the remainder passes
      // half, or reaches it with an odd quotient.
      const std::uint32_t mean =
          factor == 2 ? (block + 2) >> 2 : (block + (half - 1) + ((block >> shift) & 1)) >> shift;
      out[x] = static_cast<std::uint8_t>(mean);
    }
  }
}

}  // namespace

void average_blocks(const cv::Mat& gray, int factor, cv::Mat* averaged) {
  if (gray.type() != CV_8UC1) {
    throw std::invalid_argument("average_blocks needs an 8-bit grey image");
  }
  if (factor < 2 || factor > kMaxFactor || (factor & (factor - 1)) != 0) {
    throw std::invalid_argument("average_blocks needs a power of two from 2 to " +
                                std::to_string(kMaxFactor) + " as its factor, got " +
                                std::to_string(factor));
  }
  switch (factor) {
    case 2:
      average<2>(gray, factor, averaged);
      break;
    case 4:
      average<4>(gray, factor, averaged);
      break;
    case 8:
      average<8>(gray, factor, averaged);
      break;
    default:
      average<0>(gray, factor, averaged);
  }
}

}  // namespace scbt
