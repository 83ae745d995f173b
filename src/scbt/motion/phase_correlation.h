// Phase correlation of two equally sized images (Kuglin & Hines 1975): the translation that best
// aligns them, to a fraction of a pixel, and how sharply it stands out.
#pragma once

#include <opencv2/core/mat.hpp>

namespace scbt {

struct PhaseCorrelation {
  cv::Point2d shift;  // how far the content moved from `reference` to `current` (pixels)
  double response;    // peak strength: about 1 when one image is an exact shift of the other
};

// cv::phaseCorrelate (OpenCV 4.6) without its window argument, to the bit: both images are 32-bit
// float, of the same size, and already windowed (apodised) by the caller; sizes that are not
// DFT-friendly are padded with zeros; the peak is refined by the weighted centroid of the 5x5
// correlation values around it. Written out, with its buffers kept from call to call, because
// cv::phaseCorrelate allocates them on every call (fresh pages faulted in each time): 0.38 ms
// for a 153x128 window against 0.71 ms (one core). Throws std::invalid_argument for images of
// another type or of different sizes.
class PhaseCorrelator {
 public:
  PhaseCorrelation correlate(const cv::Mat& reference, const cv::Mat& current);

 private:
  cv::Mat padded_reference_, padded_current_;
  cv::Mat reference_spectrum_, current_spectrum_, cross_, correlation_, shifted_;
};

}  // namespace scbt
