// Shared by the tracker's image-window tests (motion estimate, view cut): random textures.
#pragma once

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace scbt {

// Uniform noise smoothed by a Gaussian of `sigma` px and stretched to 0-255: every shift of it
// is well defined, and windows of it apart are unalike.
inline cv::Mat smooth_random_texture(cv::Size size, unsigned seed, double sigma) {
  cv::Mat noise(size, CV_8U);
  cv::RNG rng(seed);
  rng.fill(noise, cv::RNG::UNIFORM, 0, 256);
  cv::GaussianBlur(noise, noise, cv::Size(0, 0), sigma);
  cv::normalize(noise, noise, 0, 255, cv::NORM_MINMAX);
  return noise;
}

}  // namespace scbt
