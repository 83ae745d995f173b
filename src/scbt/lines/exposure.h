// EDLines' published thresholds (gradient 36, anchor 8) are grey-level differences: they suit a
// frame whose intensities span a good part of the 8-bit range. A dim or washed-out camera scales
// every gradient down with its contrast (brightness x0.3 leaves a third of each edge), so the same
// thresholds keep only the strongest edges of the scene. The grey window the detector reads is
// stretched instead, as an automatic gain would stretch the image: the thresholds stay the
// published integers (scaled, 8 / 2.13 rounds to 4), and the detector's 8-bit smoothing keeps the
// precision of the few grey levels a dim edge spans. The stretch stops where the frame's own
// extremes would saturate (a bright object in a dim room keeps its edge and its level); the gain
// it leaves scales the thresholds. A frame of full contrast is detected as before.
#pragma once

#include <opencv2/core/mat.hpp>

namespace scbt {

struct ExposureOptions {
  // Stretch the grey window the detector reads by the frame's exposure gain (below).
  bool normalize = true;
  // A frame whose intensity spread (2nd to 98th percentile of its grey levels) is at least this
  // is detected as it is; a narrower one stretched by full_contrast / spread (grey_stretch).
  // Half the 8-bit range: well-exposed video spans more.
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
// `levels` (optional): the 0.1st, 2nd, 98th and 99.9th percentiles' levels.
struct IntensityLevels {
  int darkest = 0;
  int low = 0;
  int high = 255;
  int brightest = 255;
};
double intensity_spread(const cv::Mat& frame, int step, IntensityLevels* levels = nullptr);

// The factor the frame's gradients are below those of a frame of full contrast: 1 at or above
// ExposureOptions::full_contrast, full_contrast / spread below it, at most max_gain.
double exposure_gain(double spread, const ExposureOptions& options);

// How a frame of exposure `gain` (exposure_gain) with `levels` is stretched: grey levels g become
// a * (g - m) + 127.5, m the middle of the darkest and brightest levels, a = gain as far as those
// stay within 0-255 (a <= 255 / (brightest - darkest)); the rest of the gain, gain / a, is left to
// the thresholds (`residual`, threshold_for_exposure). Identity for gain <= 1.
struct GreyStretch {
  double gain = 1.0;
  double offset = 0.0;
  double residual = 1.0;  // the exposure gain the stretch leaves to the thresholds
};
GreyStretch grey_stretch(double gain, const IntensityLevels& levels);
// A grey level read on a stretched window, in the frame's own levels (levels compared across
// frames of other stretches); a negative level (unknown) stays as it is.
double unstretched_level(const GreyStretch& stretch, double level);
// A published threshold scaled for a frame of residual exposure `gain`, at least 1.
int threshold_for_exposure(int threshold, double gain);
// `gray` (8-bit grey, its own pixels) stretched in place.
void apply_grey_stretch(const GreyStretch& stretch, cv::Mat* gray);

}  // namespace scbt
