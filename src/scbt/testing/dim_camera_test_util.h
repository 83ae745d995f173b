// Shared by the tracker's dim-light tests (weak-frame retry, exposure scaling): a frame as a dim
// camera with gain noise would give it.
#pragma once

#include <opencv2/core.hpp>

namespace scbt {

// Every value of the 8-bit `image` times `brightness`, plus Gaussian noise of `noise` grey levels
// drawn from `rng`, saturated to 0..255.
inline cv::Mat dim_camera_frame(const cv::Mat& image, double brightness, double noise,
                                cv::RNG* rng) {
  cv::Mat frame;
  image.convertTo(frame, CV_32F, brightness);
  cv::Mat gain_noise(frame.size(), frame.type());
  rng->fill(gain_noise, cv::RNG::NORMAL, 0.0, noise);
  frame += gain_noise;
  frame.convertTo(frame, CV_8U);
  return frame;
}

}  // namespace scbt
