#include "scbt/tracker/motion_estimate.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>

namespace scbt {
namespace {

// `image` (8-bit grey) averaged over factor x factor blocks, as 32-bit floats (the last columns
// and rows that do not fill a block are left out, so that the scale is exactly `factor`).
void to_float(const cv::Mat& image, int factor, cv::Mat* averaged, cv::Mat* out) {
  if (factor == 1) {
    image.convertTo(*out, CV_32F);
    return;
  }
  const cv::Size small(image.cols / factor, image.rows / factor);
  cv::resize(image(cv::Rect(0, 0, small.width * factor, small.height * factor)), *averaged, small,
             0.0, 0.0, cv::INTER_AREA);
  averaged->convertTo(*out, CV_32F);
}

}  // namespace

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
  to_float(reference, factor, &averaged_, &reference_float_);
  to_float(current, factor, &averaged_, &current_float_);
  TranslationEstimate estimate;
  const cv::Point2d shift = cv::phaseCorrelate(reference_float_, current_float_,
                                               window(reference_float_.size()), &estimate.response);
  estimate.shift = Point(shift.x * factor, shift.y * factor);
  return estimate;
}

std::optional<TranslationEstimate> estimate_translation(const cv::Mat& reference,
                                                        const cv::Mat& current, int max_side) {
  TranslationEstimator estimator;
  return estimator.estimate(reference, current, max_side);
}

}  // namespace scbt
