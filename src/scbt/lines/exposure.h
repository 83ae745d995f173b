// EDLines' published thresholds (gradient 36, anchor 8) are grey-level differences: they suit a
// frame whose intensities span a good part of the 8-bit range. A dim or washed-out camera scales
// every gradient down with its contrast (brightness x0.3 leaves a third of each edge), so the same
// thresholds keep only the strongest edges of the scene. The thresholds are scaled with the
// frame's contrast instead, as an automatic gain would scale the image: a frame of full contrast
// is detected as before.
#pragma once

#include <opencv2/core/mat.hpp>

namespace scbt {

struct ExposureOptions {
  // Scale the detector's thresholds down by the frame's exposure gain (below).
  bool normalize = true;
  // A frame whose intensity spread (2nd to 98th percentile of its grey levels) is at least this
  // is detected with the published thresholds; a narrower one with thresholds scaled by
  // spread / full_contrast. Half the 8-bit range: well-exposed video spans more.
  double full_contrast = 128.0;
  // The gain stops here: at 8x a grey step of one level is all that is left of a published edge.
  double max_gain = 8.0;
  // The spread is read on every sample_step-th row and column (1200 pixels of a 640x480 frame).
  int sample_step = 16;

  // Throws std::invalid_argument naming the first bad value.
  void check() const;
};

// The grey levels' 2nd-to-98th-percentile spread of an 8-bit grey, BGR or BGRA frame, read on
// every `step`-th row and column (grey as cv::cvtColor computes it). 0 for an empty frame.
double intensity_spread(const cv::Mat& frame, int step);

// The factor the frame's gradients are below those of a frame of full contrast: 1 at or above
// ExposureOptions::full_contrast, full_contrast / spread below it, at most max_gain.
double exposure_gain(double spread, const ExposureOptions& options);

// A published threshold scaled for a frame of exposure `gain`, at least 1.
int threshold_for_exposure(int threshold, double gain);

}  // namespace scbt
