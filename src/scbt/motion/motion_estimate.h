// Global image motion between two frames, used to re-find a boundary that moved out of the search
// band (fast motion or camera swing) instead of holding it where it was.
#pragma once

#include <opencv2/core/mat.hpp>
#include <optional>

#include "scbt/geometry/polygon.h"
#include "scbt/motion/phase_correlation.h"

namespace scbt {

struct TranslationEstimate {
  Point shift;      // how far the content moved from `reference` to `current` (pixels)
  double response;  // phase-correlation peak strength, about 0..1: how much to trust it
};

// Phase correlation (phase_correlation.h, with a Hann window) between two 8-bit grey images of the
// same size; images larger than `max_side` px on a side are first averaged down by a power of two
// (the shift is scaled back: about as many px of precision as the factor). std::nullopt when the
// images are too small or differ in size. The default keeps a 380x290 window to ~0.6 ms (one core)
// instead of ~2 ms, with about a pixel of precision, well inside the search band searched around
// it. The estimator keeps its buffers and its Hann windows from call to call (a tracker measures
// every few frames, mostly at one size).
class TranslationEstimator {
 public:
  std::optional<TranslationEstimate> estimate(const cv::Mat& reference, const cv::Mat& current,
                                              int max_side = 200);

 private:
  // The Hann window of `size`: one of the last two sizes asked for, or made in place of the
  // older of them.
  const cv::Mat& window(cv::Size size);
  // `image` averaged down by `factor`, as 32-bit floats multiplied by the Hann window, into the
  // top left of *out, sized `dft_size` and zero elsewhere.
  void to_windowed_float(const cv::Mat& image, int factor, cv::Size dft_size, cv::Mat* out);

  cv::Mat averaged_, reference_float_, current_float_;
  cv::Mat windows_[2];
  int older_window_ = 0;
  PhaseCorrelator correlator_;
};

// One estimate with buffers of its own (TranslationEstimator::estimate).
std::optional<TranslationEstimate> estimate_translation(const cv::Mat& reference,
                                                        const cv::Mat& current, int max_side = 200);

}  // namespace scbt
