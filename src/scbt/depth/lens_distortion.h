// OpenCV's radial-tangential lens distortion on normalised image coordinates
// (the model of cv::projectPoints / ROS plumb_bob and rational_polynomial).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace scbt {

// Distorted normalised coordinates of the ideal ones `xy`; coefficients k1 k2 p1 p2 [k3 [k4 k5
// k6]] (fewer are zero-padded).
Eigen::Vector2d distort_normalised(const std::vector<double>& coefficients,
                                   const Eigen::Vector2d& xy);

// Inverse of distort_normalised by fixed-point iteration (as cv::undistortPoints does), stopped
// when the re-distorted point is within 1e-12 of `distorted` or after 50 steps.
Eigen::Vector2d undistort_normalised(const std::vector<double>& coefficients,
                                     const Eigen::Vector2d& distorted);

}  // namespace scbt
