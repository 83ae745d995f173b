#include "scbt/lines/exposure.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
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

namespace {

// cv::cvtColor's BGR to grey weights in 14-bit fixed point (one channel: the level itself).
template <bool kGrey>
int grey_level(const std::uint8_t* p) {
  if constexpr (kGrey) {
    return p[0];
  } else {
    return (p[0] * 1868 + p[1] * 9617 + p[2] * 4899 + (1 << 13)) >> 14;
  }
}

// Counts the grey levels of every step-th pixel of every step-th row (from step / 2) into
// `histogram`; returns how many were counted. Consecutive samples go to four histograms in turn,
// summed at the end: on a dark or flat frame most samples hit one level, and increments of one
// counter would wait on each other.
template <bool kGrey>
int count_levels(const cv::Mat& frame, int step, std::array<int, 256>* histogram) {
  const int first = step / 2;
  if (first >= frame.cols) return 0;
  const int columns = (frame.cols - 1 - first) / step + 1;
  const std::ptrdiff_t stride = static_cast<std::ptrdiff_t>(step) * frame.channels();
  std::array<std::array<int, 256>, 4> counts{};
  // A camera's frame is in memory, not in the cache, and samples `step` pixels apart defeat the
  // hardware's fetching ahead: the rows kAhead samples down are asked for while this one is read.
  constexpr int kAhead = 4;
  const std::ptrdiff_t row_bytes = static_cast<std::ptrdiff_t>(frame.cols) * frame.channels();
  const auto fetch_row = [&](int r) {
    if (r >= frame.rows) return;
    const std::uint8_t* row = frame.ptr<std::uint8_t>(r);
    for (std::ptrdiff_t b = 0; b < row_bytes; b += 64) __builtin_prefetch(row + b);
  };
  for (int k = 0; k < kAhead; ++k) fetch_row(first + k * step);
  int rows = 0;
  for (int r = first; r < frame.rows; r += step, ++rows) {
    fetch_row(r + kAhead * step);
    const std::uint8_t* p =
        frame.ptr<std::uint8_t>(r) + static_cast<std::ptrdiff_t>(first) * frame.channels();
    int c = 0;
    for (; c + 4 <= columns; c += 4, p += 4 * stride) {
      ++counts[0][grey_level<kGrey>(p)];
      ++counts[1][grey_level<kGrey>(p + stride)];
      ++counts[2][grey_level<kGrey>(p + 2 * stride)];
      ++counts[3][grey_level<kGrey>(p + 3 * stride)];
    }
    for (; c < columns; ++c, p += stride) ++counts[0][grey_level<kGrey>(p)];
  }
  for (int level = 0; level < 256; ++level) {
    (*histogram)[level] = counts[0][level] + counts[1][level] + counts[2][level] + counts[3][level];
  }
  return rows * columns;
}

}  // namespace

double intensity_spread(const cv::Mat& frame, int step, IntensityLevels* levels) {
  if (frame.empty() || frame.depth() != CV_8U) return 0.0;
  step = std::max(step, 1);
  std::array<int, 256> histogram{};
  const int count = frame.channels() == 1 ? count_levels<true>(frame, step, &histogram)
                                          : count_levels<false>(frame, step, &histogram);
  if (count == 0) return 0.0;
  // The levels below which 0.1 %, 2 %, 98 % and 99.9 % of the samples lie.
  const int darkest_rank = count / 1000, low_rank = count / 50;
  const int high_rank = count - 1 - count / 50, brightest_rank = count - 1 - count / 1000;
  int darkest = -1, low = -1, high = -1, brightest = -1, seen = 0;
  for (int level = 0; level < 256; ++level) {
    seen += histogram[level];
    if (darkest < 0 && seen > darkest_rank) darkest = level;
    if (low < 0 && seen > low_rank) low = level;
    if (high < 0 && seen > high_rank) high = level;
    if (seen > brightest_rank) {
      brightest = level;
      break;
    }
  }
  if (levels != nullptr) *levels = {darkest, low, high, brightest};
  return static_cast<double>(high - low);
}

double exposure_gain(double spread, const ExposureOptions& options) {
  if (!(spread > 0.0)) return options.max_gain;
  return std::clamp(options.full_contrast / spread, 1.0, options.max_gain);
}

GreyStretch grey_stretch(double gain, const IntensityLevels& levels) {
  if (!(gain > 1.0)) return {};
  const double range = std::max(1, levels.brightest - levels.darkest);
  const double applied = std::min(gain, 255.0 / range);
  if (!(applied > 1.0)) return {1.0, 0.0, gain};
  const double middle = 0.5 * (levels.darkest + levels.brightest);
  return {applied, 127.5 - applied * middle, gain / applied};
}

double unstretched_level(const GreyStretch& stretch, double level) {
  if (level < 0.0 || !(stretch.gain > 1.0)) return level;
  return std::clamp((level - stretch.offset) / stretch.gain, 0.0, 255.0);
}

int threshold_for_exposure(int threshold, double gain) {
  return std::max(1, static_cast<int>(std::lround(threshold / gain)));
}

void apply_grey_stretch(const GreyStretch& stretch, cv::Mat* gray) {
  if (stretch.gain > 1.0) gray->convertTo(*gray, -1, stretch.gain, stretch.offset);
}

}  // namespace scbt
