#include "scbt/motion/phase_correlation.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <opencv2/core.hpp>
#include <stdexcept>

namespace scbt {
namespace {

// Divides each value of the cross-power `spectrum` (CCS-packed, the layout cv::dft gives a real
// image's transform) by its magnitude, regularised by FLT_EPSILON, in the arithmetic
// cv::phaseCorrelate uses (OpenCV 4.6), so that the tracker's measured motion is what it was
// measured with.
void keep_phase_only(cv::Mat* spectrum) {
  const int rows = spectrum->rows, cols = spectrum->cols;
  const float eps = FLT_EPSILON;
  const auto real = [eps](float* value) { *value = *value / (std::abs(*value) + eps); };
  // Columns 0 and, for an even width, cols - 1 hold real-valued 1-D transforms packed down the
  // rows: a real first value, complex pairs (re, im) on rows (1, 2), (3, 4), ..., and for an even
  // height a real last value. Their division runs in double.
  const int packed_columns = cols % 2 == 0 ? 2 : 1;
  for (int c = 0; c < packed_columns; ++c) {
    const int x = c == 0 ? 0 : cols - 1;
    real(&spectrum->at<float>(0, x));
    if (rows % 2 == 0) real(&spectrum->at<float>(rows - 1, x));
    for (int r = 1; r + 1 < rows; r += 2) {
      float& re = spectrum->at<float>(r, x);
      float& im = spectrum->at<float>(r + 1, x);
      const float magnitude = static_cast<float>(
          std::sqrt(static_cast<double>(re) * re + static_cast<double>(im) * im));
      const double denominator =
          static_cast<double>(magnitude) * magnitude + static_cast<double>(eps);
      const double unit_re = static_cast<double>(re) * magnitude;
      const double unit_im = static_cast<double>(im) * magnitude;
      re = static_cast<float>(unit_re / denominator);
      im = static_cast<float>(unit_im / denominator);
    }
  }
  // The other columns are complex pairs along each row; their division runs in float, then double.
  const int pairs_end = cols % 2 == 0 ? cols - 1 : cols;  // one past the last pair
  for (int r = 0; r < rows; ++r) {
    float* row = spectrum->ptr<float>(r);
    for (int x = 1; x + 1 < pairs_end; x += 2) {
      const float re = row[x], im = row[x + 1];
      const float magnitude = static_cast<float>(
          std::sqrt(static_cast<double>(re) * re + static_cast<double>(im) * im));
      const double denominator = static_cast<double>(magnitude * magnitude + eps);
      row[x] = static_cast<float>(static_cast<double>(re * magnitude) / denominator);
      row[x + 1] = static_cast<float>(static_cast<double>(im * magnitude) / denominator);
    }
  }
}

// Row or column `i` of `n` after the circular shift that moves zero lag to n / 2 (as
// cv::phaseCorrelate reads the correlation): the index it came from.
int shifted_from(int i, int n) { return (i + n - n / 2) % n; }

}  // namespace

PhaseCorrelation PhaseCorrelator::correlate(const cv::Mat& reference, const cv::Mat& current) {
  if (reference.type() != CV_32FC1 || current.type() != CV_32FC1 ||
      reference.size() != current.size() || reference.empty()) {
    throw std::invalid_argument("phase correlation needs two 32-bit float images of one size");
  }
  const int rows = cv::getOptimalDFTSize(reference.rows);
  const int cols = cv::getOptimalDFTSize(reference.cols);
  const cv::Mat* padded_reference = &reference;
  const cv::Mat* padded_current = &current;
  if (rows != reference.rows || cols != reference.cols) {
    const int bottom = rows - reference.rows, right = cols - reference.cols;
    cv::copyMakeBorder(reference, padded_reference_, 0, bottom, 0, right, cv::BORDER_CONSTANT, 0);
    cv::copyMakeBorder(current, padded_current_, 0, bottom, 0, right, cv::BORDER_CONSTANT, 0);
    padded_reference = &padded_reference_;
    padded_current = &padded_current_;
  }
  cv::dft(*padded_reference, reference_spectrum_, cv::DFT_REAL_OUTPUT);
  cv::dft(*padded_current, current_spectrum_, cv::DFT_REAL_OUTPUT);
  // The cross-power spectrum R C* normalised to unit magnitude: its inverse transform peaks at
  // minus the shift (C = R e^{-i w d}, so R C* / |R C*| = e^{i w d}).
  cv::mulSpectrums(reference_spectrum_, current_spectrum_, cross_, 0, /*conjB=*/true);
  keep_phase_only(&cross_);
  cv::dft(cross_, correlation_, cv::DFT_INVERSE);
  // Zero shift moved to the middle, as cv::phaseCorrelate reads it.
  shifted_.create(rows, cols, CV_32F);
  for (int r = 0; r < rows; ++r) {
    const float* from = correlation_.ptr<float>(shifted_from(r, rows));
    float* to = shifted_.ptr<float>(r);
    for (int c = 0; c < cols; ++c) to[c] = from[shifted_from(c, cols)];
  }
  cv::Point peak;
  cv::minMaxLoc(shifted_, nullptr, nullptr, nullptr, &peak);
  // Weighted centroid of the 5x5 values around the peak, clipped to the correlation's borders.
  double sum = 0.0, sum_x = 0.0, sum_y = 0.0;
  for (int y = std::max(peak.y - 2, 0); y <= std::min(peak.y + 2, rows - 1); ++y) {
    const float* row = shifted_.ptr<float>(y);
    for (int x = std::max(peak.x - 2, 0); x <= std::min(peak.x + 2, cols - 1); ++x) {
      sum_x += static_cast<double>(x) * row[x];
      sum_y += static_cast<double>(y) * row[x];
      sum += static_cast<double>(row[x]);
    }
  }
  PhaseCorrelation result;
  // The inverse transform is unscaled: a perfect match peaks at rows * cols.
  result.response = sum / (rows * cols);
  sum += DBL_EPSILON;
  result.shift = cv::Point2d(cols / 2.0 - sum_x / sum, rows / 2.0 - sum_y / sum);
  return result;
}

}  // namespace scbt
