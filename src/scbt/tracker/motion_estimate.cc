#include "scbt/tracker/motion_estimate.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>

namespace scbt {
namespace {

// `image` (8-bit grey) averaged over factor x factor blocks, as 32-bit floats (the last columns
// and rows that do not fill a block are left out, so that the scale is exactly `factor`).
void to_float(const cv::Mat& image, int factor, cv::Mat* out) {
  if (factor == 1) {
    image.convertTo(*out, CV_32F);
    return;
  }
  const cv::Size small(image.cols / factor, image.rows / factor);
  cv::Mat averaged;
  cv::resize(image(cv::Rect(0, 0, small.width * factor, small.height * factor)), averaged, small,
             0.0, 0.0, cv::INTER_AREA);
  averaged.convertTo(*out, CV_32F);
}

}  // namespace

std::optional<TranslationEstimate> estimate_translation(const cv::Mat& reference,
                                                        const cv::Mat& current, int max_side) {
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
  cv::Mat reference_float, current_float, window;
  to_float(reference, factor, &reference_float);
  to_float(current, factor, &current_float);
  cv::createHanningWindow(window, reference_float.size(), CV_32F);
  TranslationEstimate estimate;
  const cv::Point2d shift =
      cv::phaseCorrelate(reference_float, current_float, window, &estimate.response);
  estimate.shift = Point(shift.x * factor, shift.y * factor);
  return estimate;
}

}  // namespace scbt
