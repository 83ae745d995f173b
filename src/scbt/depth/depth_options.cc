#include "scbt/depth/depth_options.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace scbt {
namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("depth options: " + what);
}

bool positive(double v) { return std::isfinite(v) && v > 0.0; }

}  // namespace

void DepthOptions::check() const {
  require(positive(depth_scale), "depth_scale must be a positive number");
  require(std::isfinite(min_depth) && min_depth >= 0.0, "min_depth must be >= 0");
  require(std::isfinite(max_depth) && max_depth > min_depth, "max_depth must exceed min_depth");
  require(positive(sample_step), "sample_step must be positive");
  require(std::isfinite(window_offset) && window_offset >= 0.0 && window_offset <= 20.0,
          "window_offset must be in [0, 20] pixels");
  require(window_length >= 1 && window_length <= 20, "window_length must be in [1, 20]");
  require(window_half_width >= 0 && window_half_width <= 10,
          "window_half_width must be in [0, 10]");
  require(std::isfinite(noise_at_1m) && noise_at_1m >= 0.0, "noise_at_1m must be >= 0");
  require(positive(outlier_sigmas), "outlier_sigmas must be positive");
  require(positive(tolerance_floor), "tolerance_floor must be positive");
  require(min_surface_pixels >= 1, "min_surface_pixels must be >= 1");
  require(neighbour_span >= 0 && neighbour_span <= 16, "neighbour_span must be in [0, 16]");
  require(plane_iterations >= 1 && plane_iterations <= 50, "plane_iterations must be in [1, 50]");
  require(min_valid_points >= 3, "min_valid_points must be >= 3");
  require(
      std::isfinite(min_valid_fraction) && min_valid_fraction >= 0.0 && min_valid_fraction <= 1.0,
      "min_valid_fraction must be in [0, 1]");
  require(positive(circle_max_relative_rms), "circle_max_relative_rms must be positive");
  require(std::isfinite(outline_normal_max_angle) && outline_normal_max_angle >= 0.0 &&
              outline_normal_max_angle <= 90.0,
          "outline_normal_max_angle must be in [0, 90] degrees");
}

}  // namespace scbt
