// Test inputs for the video reader: an MJPG AVI with a frame the reader skips without an error.
#pragma once

#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

namespace scbt {

// Writes `frames` (same size, 8-bit BGR) as an MJPG AVI at 10 fps whose frame `dropped`
// (1-based) is a zero-size chunk, the way AVI marks a dropped frame: FFmpeg's reader skips it
// silently and returns the next frame in its place; only its timestamp tells. Returns "" on
// success, else what went wrong.
std::string write_avi_with_a_dropped_frame(const std::string& path,
                                           const std::vector<cv::Mat>& frames, int dropped);

}  // namespace scbt
