// The input checks every tracker (scbt's and the peers') applies, so that all of them reject the
// same frames and polygons with the same messages.
#pragma once

#include <opencv2/core/mat.hpp>

#include "scbt/geometry/polygon.h"

namespace scbt {

// Converts an 8-bit frame of 1, 3 or 4 channels to grey (a copy for grey input), into a buffer of
// `gray`'s own: reused when `gray` alone holds it, never one another Mat shares, so the result
// never aliases the frame and an earlier frame `gray` still viewed is never written.
// Throws std::invalid_argument for anything else.
void to_gray(const cv::Mat& frame, cv::Mat* gray);

// The checks of an init: 8-bit frame of 1, 3 or 4 channels, a usable boundary polygon
// (check_boundary_polygon) whose vertices lie inside the frame. Writes the grey frame to `gray`.
// Throws std::invalid_argument naming the problem.
void check_tracker_init(const cv::Mat& frame, const Polygon& polygon, cv::Mat* gray);

// Throws std::invalid_argument when `frame` is not `expected` in size (frame sizes must not
// change during a sequence).
void check_frame_size(const cv::Mat& frame, const cv::Size& expected);

}  // namespace scbt
