// The pinhole camera of an RGB-D sensor: intrinsics, OpenCV's lens distortion model, and the
// mapping between pixels and 3-D points in the camera frame (x right, y down, z forward, metres).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "scbt/geometry/polygon.h"

namespace scbt {

struct PinholeIntrinsics {
  double fx = 525.0;  // focal lengths (pixels)
  double fy = 525.0;
  double cx = 319.5;  // principal point (pixels)
  double cy = 239.5;
  // OpenCV's order: k1 k2 p1 p2 [k3 [k4 k5 k6]]; empty = no distortion. ROS's plumb_bob is the
  // 5-coefficient form.
  std::vector<double> distortion;

  // Throws std::invalid_argument naming the first bad value (non-positive or non-finite focal
  // length, non-finite principal point, a coefficient count other than 0, 4, 5 or 8).
  void check() const;
  bool has_distortion() const;
};

// Parses "fx,fy,cx,cy" (no distortion); throws std::invalid_argument naming what is wrong.
PinholeIntrinsics parse_intrinsics(const std::string& text);

// Normalised image coordinates (x/z, y/z) of the undistorted ray through `pixel`.
Eigen::Vector2d undistorted_normalised(const PinholeIntrinsics& camera, const Point& pixel);

// The ray through `pixel` scaled to z = 1: a point at depth z is z * ray.
Eigen::Vector3d pixel_ray(const PinholeIntrinsics& camera, const Point& pixel);

// The pixel where a camera-frame point (z > 0) is imaged, distortion applied.
Point project_point(const PinholeIntrinsics& camera, const Eigen::Vector3d& point);

// The boundary's vertices moved to where an ideal (distortion-free) camera with the same
// fx, fy, cx, cy would see them; unchanged without distortion.
Polygon undistort_polygon(const PinholeIntrinsics& camera, const Polygon& polygon);

}  // namespace scbt
