// Global image motion between two frames, used to re-find a boundary that moved out of the search
// band (fast motion or camera swing) instead of holding it where it was.
#pragma once

#include <opencv2/core/mat.hpp>
#include <optional>

#include "scbt/geometry/polygon.h"

namespace scbt {

struct TranslationEstimate {
  Point shift;      // how far the content moved from `reference` to `current` (pixels)
  double response;  // phase-correlation peak strength, 0..1: how much to trust it
};

// Phase correlation (cv::phaseCorrelate with a Hann window) between two 8-bit grey images of the
// same size; images larger than 200 px on a side are first averaged down by a power of two (the
// shift is scaled back: about a pixel of precision). std::nullopt when the images are too small
// or differ in size.
std::optional<TranslationEstimate> estimate_translation(const cv::Mat& reference,
                                                        const cv::Mat& current);

}  // namespace scbt
