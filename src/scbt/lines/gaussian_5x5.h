// The Gaussian smoothing EDLines starts with (5x5, sigma 1), bit for bit what
// cv::GaussianBlur(gray, out, cv::Size(5, 5), 1.0, 1.0) gives on an 8-bit image, written out
// because it is most of a frame's pixel work: OpenCV 4.6 computes it exactly in fixed point
// (the kernel (14, 62, 104, 62, 14) / 256 in each direction, one rounding at the end, borders
// reflected without repeating the edge pixel, BORDER_REFLECT_101), and so does this, about 2.2x
// faster (scbt_line_bench: BM_Gaussian5x5 against BM_OpenCvGaussian5x5).
#pragma once

#include <opencv2/core/mat.hpp>

#include "scbt/lines/row_spans.h"

namespace scbt {

// Smooths `gray` (CV_8UC1, any stride, any size) into *out (CV_8UC1 of gray's size; reallocated
// only when its size or type differs). `out` must not share gray's pixels. Throws
// std::invalid_argument for another type.
void gaussian_blur_5x5(const cv::Mat& gray, cv::Mat* out);

// The same, computed only on the pixels of `where` (a set on gray's window), for a detector
// that needs the smoothed image near a boundary only. A pixel (r, c) of `where` comes out as the
// whole image's blur when column c is in `where` on each row within two of r (reflected at the
// window's ends, as the blur reads them); other pixels of `where` come out unspecified, and the
// pixels outside `where` are left as they were. Throws std::invalid_argument for another type or
// a `where` of another size.
void gaussian_blur_5x5(const cv::Mat& gray, const RowSpans& where, cv::Mat* out);

}  // namespace scbt
