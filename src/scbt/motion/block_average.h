// A grey image averaged down over square blocks, as the phase correlation of the measured motion
// reads it (motion_estimate.h).
#pragma once

#include <opencv2/core/mat.hpp>

namespace scbt {

// Block sums stay within an int up to this factor (2048^2 x 255 < 2^31).
constexpr int kMaxFactor = 2048;

// `gray` (8-bit, one channel) averaged over factor x factor blocks (factor a power of two, 2 to
// kMaxFactor) into *averaged, (cols / factor) x (rows / factor); the last columns and rows that do
// not fill a block are left out. Equal to cv::resize's INTER_AREA of the full blocks to the bit (a
// block's mean rounded half up for 2x2 blocks, half to even for larger ones), written out because
// OpenCV's area path for 4x4 blocks and more costs about as much as the phase correlation it
// feeds. Throws std::invalid_argument for another image type or factor.
void average_blocks(const cv::Mat& gray, int factor, cv::Mat* averaged);

}  // namespace scbt
