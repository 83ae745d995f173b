#include "scbt/tracker/motion_estimate.h"

#include <opencv2/imgproc.hpp>

namespace scbt {

std::optional<TranslationEstimate> estimate_translation(const cv::Mat& reference,
                                                        const cv::Mat& current) {
  constexpr int kMinSide = 16;
  if (reference.size() != current.size() || reference.cols < kMinSide ||
      reference.rows < kMinSide || reference.type() != CV_8UC1 || current.type() != CV_8UC1) {
    return std::nullopt;
  }
  cv::Mat reference_float, current_float, window;
  reference.convertTo(reference_float, CV_32F);
  current.convertTo(current_float, CV_32F);
  cv::createHanningWindow(window, reference.size(), CV_32F);
  TranslationEstimate estimate;
  const cv::Point2d shift =
      cv::phaseCorrelate(reference_float, current_float, window, &estimate.response);
  estimate.shift = shift;
  return estimate;
}

}  // namespace scbt
