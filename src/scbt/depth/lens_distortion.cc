#include "scbt/depth/lens_distortion.h"

#include <array>

namespace scbt {
namespace {

std::array<double, 8> padded(const std::vector<double>& coefficients) {
  std::array<double, 8> k{};
  for (std::size_t i = 0; i < coefficients.size() && i < k.size(); ++i) k[i] = coefficients[i];
  return k;
}

}  // namespace

Eigen::Vector2d distort_normalised(const std::vector<double>& coefficients,
                                   const Eigen::Vector2d& xy) {
  const auto [k1, k2, p1, p2, k3, k4, k5, k6] = padded(coefficients);
  const double x = xy.x(), y = xy.y();
  const double r2 = x * x + y * y, r4 = r2 * r2, r6 = r4 * r2;
  const double radial = (1.0 + k1 * r2 + k2 * r4 + k3 * r6) / (1.0 + k4 * r2 + k5 * r4 + k6 * r6);
  return {x * radial + 2.0 * p1 * x * y + p2 * (r2 + 2.0 * x * x),
          y * radial + p1 * (r2 + 2.0 * y * y) + 2.0 * p2 * x * y};
}

Eigen::Vector2d undistort_normalised(const std::vector<double>& coefficients,
                                     const Eigen::Vector2d& distorted) {
  if (coefficients.empty()) return distorted;
  Eigen::Vector2d xy = distorted;
  for (int step = 0; step < 50; ++step) {
    const Eigen::Vector2d error = distort_normalised(coefficients, xy) - distorted;
    if (error.squaredNorm() < 1e-24) break;
    xy -= error;
  }
  return xy;
}

}  // namespace scbt
