// A plane through 3-D points, robust to outliers.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "scbt/depth/depth_options.h"

namespace scbt {

struct PlaneFit {
  bool found = false;               // false with fewer than 3 inliers or collinear points
  Eigen::Vector3d normal{0, 0, 0};  // unit; points towards the camera (normal . point < 0)
  double offset = 0.0;              // the plane is normal . x = offset
  double rms = 0.0;                 // RMS distance of the inliers to the plane (metres)
  std::vector<bool> inlier;         // per input point
  int n_inliers = 0;
};

// A least-median plane through evenly spaced triples (robust to a coherent wrong stretch of
// the rim), then least-squares planes (the smallest principal axis of the covariance) refitted
// up to options.plane_iterations times on the points within max(surface_tolerance(z), 3 * 1.4826
// * median distance) of the previous plane: the noise model bounds what a flat rim needs, the
// median lets a bent one keep its points. Points are in boundary order; non-finite ones are
// ignored.
PlaneFit fit_plane_robust(const std::vector<Eigen::Vector3d>& points, const DepthOptions& options);

// Where the camera ray `ray` (a point at depth z is z * ray) meets the plane; false when it
// runs parallel to it or meets it behind the camera.
bool intersect_ray_with_plane(const PlaneFit& plane, const Eigen::Vector3d& ray,
                              Eigen::Vector3d* point);

}  // namespace scbt
