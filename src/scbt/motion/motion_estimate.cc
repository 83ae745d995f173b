#include "scbt/motion/motion_estimate.h"

#include <algorithm>
#include <cstdint>
#include <opencv2/imgproc.hpp>

#include "scbt/motion/block_average.h"

namespace scbt {

void TranslationEstimator::to_windowed_float(const cv::Mat& image, int factor, cv::Size dft_size,
                                             cv::Mat* out) {
  // Averaged over factor x factor blocks; the last columns and rows that do not fill a block are
  // left out, so that the scale is exactly `factor`.
  const cv::Mat* averaged = &image;
  if (factor > 1) {
    average_blocks(image, factor, &averaged_);
    averaged = &averaged_;
  }
  const cv::Mat& hann = window(averaged->size());
  out->create(dft_size, CV_32F);  // the same DFT size from call to call reuses the buffer
  for (int r = 0; r < dft_size.height; ++r) {
    float* row = out->ptr<float>(r);
    if (r >= averaged->rows) {
      std::fill(row, row + dft_size.width, 0.0f);
      continue;
    }
    const std::uint8_t* in = averaged->ptr<std::uint8_t>(r);
    const float* w = hann.ptr<float>(r);
    for (int c = 0; c < averaged->cols; ++c) row[c] = w[c] * static_cast<float>(in[c]);
    std::fill(row + averaged->cols, row + dft_size.width, 0.0f);
  }
}

const cv::Mat& TranslationEstimator::window(cv::Size size) {
  for (const cv::Mat& w : windows_) {
    if (w.size() == size) return w;
  }
  cv::Mat& made = windows_[older_window_];
  older_window_ = 1 - older_window_;
  cv::createHanningWindow(made, size, CV_32F);
  return made;
}

std::optional<TranslationEstimate> TranslationEstimator::estimate(const cv::Mat& reference,
                                                                  const cv::Mat& current,
                                                                  int max_side) {
  constexpr int kMinSide = 16;
  if (reference.size() != current.size() || reference.cols < kMinSide ||
      reference.rows < kMinSide || reference.type() != CV_8UC1 || current.type() != CV_8UC1) {
    return std::nullopt;
  }
  int factor = 1;
  while (std::max(reference.cols, reference.rows) / factor > max_side &&
         std::min(reference.cols, reference.rows) / (2 * factor) >= kMinSide) {
    factor *= 2;
  }
  const cv::Size dft_size(cv::getOptimalDFTSize(reference.cols / factor),
                          cv::getOptimalDFTSize(reference.rows / factor));
  to_windowed_float(reference, factor, dft_size, &reference_float_);
  to_windowed_float(current, factor, dft_size, &current_float_);
  const PhaseCorrelation correlation = correlator_.correlate(reference_float_, current_float_);
  TranslationEstimate estimate;
  estimate.shift = Point(correlation.shift.x * factor, correlation.shift.y * factor);
  estimate.response = correlation.response;
  return estimate;
}

std::optional<TranslationEstimate> estimate_translation(const cv::Mat& reference,
                                                        const cv::Mat& current, int max_side) {
  TranslationEstimator estimator;
  return estimator.estimate(reference, current, max_side);
}

}  // namespace scbt
