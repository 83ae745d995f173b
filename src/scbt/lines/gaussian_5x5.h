// The Gaussian smoothing EDLines starts with (5x5, sigma 1), bit for bit what
// cv::GaussianBlur(gray, out, cv::Size(5, 5), 1.0, 1.0) gives on an 8-bit image, written out
// because it is most of a frame's pixel work: OpenCV 4.6 computes it exactly in fixed point
// (the kernel (14, 62, 104, 62, 14) / 256 in each direction, one rounding at the end, borders
// reflected without repeating the edge pixel, BORDER_REFLECT_101), and so does this, about 1.5x
// faster (scbt_line_bench: BM_Gaussian5x5 against BM_OpenCvGaussian5x5).
#pragma once

#include <opencv2/core/mat.hpp>

namespace scbt {

// Smooths `gray` (CV_8UC1, any stride, any size) into *out (CV_8UC1 of gray's size; reallocated
// only when its size or type differs). `out` must not share gray's pixels. Throws
// std::invalid_argument for another type.
void gaussian_blur_5x5(const cv::Mat& gray, cv::Mat* out);

}  // namespace scbt
