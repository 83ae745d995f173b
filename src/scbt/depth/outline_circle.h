// A circle's image is an ellipse, and the ellipse fixes the circle's orientation: the cone of
// rays through it has exactly two families of circular sections (Safaee-Rad et al. 1992). At a
// distance where depth is noisy (sigma ~ z^2) the outline measures a rim's tilt better than
// its depth does, so for a near-circular rim the normal comes from the outline and only the
// plane's distance from depth.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

namespace scbt {

struct OutlineNormals {
  bool found = false;  // false when the rays' conic is not an ellipse (too few or degenerate)
  // The normals (unit, towards the camera) of the two planes that cut the cone of `rays` in a
  // circle; equal for a rim seen face-on.
  std::array<Eigen::Vector3d, 2> normals;
};

// Fits a conic a x^2 + b xy + c y^2 + d x + e y + f = 0 to the rays' normalised image points
// (x, y) = (ray.x / ray.z, ray.y / ray.z), constrained to be an ellipse (Fitzgibbon, Pilu and
// Fisher 1999), and returns the normals of the cone's circular sections. Non-finite rays are
// ignored; at least 6 are needed.
OutlineNormals circle_normals_from_outline(const std::vector<Eigen::Vector3d>& rays);

}  // namespace scbt
