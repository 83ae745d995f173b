#include "scbt/lines/exposure.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace scbt {

void ExposureOptions::check() const {
  if (!(full_contrast > 0.0 && full_contrast <= 255.0)) {
    throw std::invalid_argument("exposure full_contrast must be in (0, 255]");
  }
  if (!(max_gain >= 1.0 && max_gain <= 64.0)) {
    throw std::invalid_argument("exposure max_gain must be in [1, 64]");
  }
  if (sample_step < 1) throw std::invalid_argument("exposure sample_step must be >= 1");
}

double intensity_spread(const cv::Mat& frame, int step) {
  if (frame.empty() || frame.depth() != CV_8U) return 0.0;
  step = std::max(step, 1);
  const int channels = frame.channels();
  std::array<int, 256> histogram{};
  int count = 0;
  for (int r = step / 2; r < frame.rows; r += step) {
    const std::uint8_t* row = frame.ptr<std::uint8_t>(r);
    for (int c = step / 2; c < frame.cols; c += step) {
      const std::uint8_t* p = row + c * channels;
      // cv::cvtColor's BGR to grey weights in 14-bit fixed point.
      const int grey =
          channels == 1 ? p[0] : (p[0] * 1868 + p[1] * 9617 + p[2] * 4899 + (1 << 13)) >> 14;
      ++histogram[grey];
      ++count;
    }
  }
  if (count == 0) return 0.0;
  // The levels below which 2 % and 98 % of the samples lie.
  const int low_rank = count / 50, high_rank = count - 1 - count / 50;
  int low = -1, high = -1, seen = 0;
  for (int level = 0; level < 256; ++level) {
    seen += histogram[level];
    if (low < 0 && seen > low_rank) low = level;
    if (seen > high_rank) {
      high = level;
      break;
    }
  }
  return static_cast<double>(high - low);
}

double exposure_gain(double spread, const ExposureOptions& options) {
  if (!(spread > 0.0)) return options.max_gain;
  return std::clamp(options.full_contrast / spread, 1.0, options.max_gain);
}

int threshold_for_exposure(int threshold, double gain) {
  return std::max(1, static_cast<int>(std::lround(threshold / gain)));
}

}  // namespace scbt
