#include "scbt/tracker/block_average.h"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace scbt {

void average_blocks(const cv::Mat& gray, int factor, cv::Mat* averaged) {
  if (gray.type() != CV_8UC1) {
    throw std::invalid_argument("average_blocks needs an 8-bit grey image");
  }
  if (factor < 2 || factor > kMaxFactor || (factor & (factor - 1)) != 0) {
    throw std::invalid_argument("average_blocks needs a power of two from 2 to " +
                                std::to_string(kMaxFactor) + " as its factor, got " +
                                std::to_string(factor));
  }
  const int width = gray.cols / factor, height = gray.rows / factor;
  averaged->create(height, width, CV_8U);
  int shift = 0;  // log2(factor * factor)
  while ((1 << shift) < factor * factor) ++shift;
  const int half = 1 << (shift - 1);
  const int used = width * factor;
  // Column sums of one band of `factor` rows.
  thread_local std::vector<std::uint32_t> columns;
  columns.resize(static_cast<size_t>(used));
  for (int y = 0; y < height; ++y) {
    std::uint32_t* __restrict sum = columns.data();
    const std::uint8_t* __restrict first = gray.ptr<std::uint8_t>(y * factor);
    for (int c = 0; c < used; ++c) sum[c] = first[c];
    for (int k = 1; k < factor; ++k) {
      const std::uint8_t* __restrict row = gray.ptr<std::uint8_t>(y * factor + k);
      for (int c = 0; c < used; ++c) sum[c] += row[c];
    }
    std::uint8_t* out = averaged->ptr<std::uint8_t>(y);
    for (int x = 0; x < width; ++x) {
      int block = 0;
      for (int j = 0; j < factor; ++j) block += sum[x * factor + j];
      int mean;
      if (factor == 2) {
        mean = (block + 2) >> 2;
      } else {
        const int whole = block >> shift, rest = block - (whole << shift);
        mean = whole + ((rest > half || (rest == half && (whole & 1) != 0)) ? 1 : 0);
      }
      out[x] = static_cast<std::uint8_t>(mean);
    }
  }
}

}  // namespace scbt
