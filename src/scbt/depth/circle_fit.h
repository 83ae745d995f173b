// A circle in 3-D through points on a known plane (a bowl's or cup's rim).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace scbt {

struct CircleFit {
  bool found = false;  // false with fewer than 3 points or collinear ones
  Eigen::Vector3d centre{0, 0, 0};
  Eigen::Vector3d normal{0, 0, 0};  // the plane's normal
  double radius = 0.0;
  double rms = 0.0;  // RMS of |point - centre| - radius over the fitted points
};

// Circle in the plane with unit `normal` through `origin`: the points are projected onto the
// plane, an algebraic (Kasa) fit starts Gauss-Newton on the geometric distances
// sum (|p - c| - r)^2 (up to `iterations` steps; 0 = the algebraic fit alone). Non-finite points
// are ignored.
CircleFit fit_circle_in_plane(const std::vector<Eigen::Vector3d>& points,
                              const Eigen::Vector3d& origin, const Eigen::Vector3d& normal,
                              int iterations = 10);

// RMS of |point - centre| - radius for the points projected onto the circle's plane.
double circle_rms(const CircleFit& circle, const std::vector<Eigen::Vector3d>& points);

}  // namespace scbt
