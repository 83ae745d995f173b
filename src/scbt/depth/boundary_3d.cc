#include "scbt/depth/boundary_3d.h"

#include <limits>
#include <stdexcept>

#include "scbt/depth/boundary_samples.h"
#include "scbt/depth/curve_centroid.h"
#include "scbt/depth/curve_outliers.h"
#include "scbt/depth/depth_window.h"
#include "scbt/depth/plane_fit.h"

namespace scbt {
namespace {

const Eigen::Vector3d kNan = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());

void check_depth_image(const cv::Mat& depth) {
  if (depth.empty()) throw std::invalid_argument("depth image is empty");
  if (depth.type() != CV_16UC1 && depth.type() != CV_32FC1)
    throw std::invalid_argument(
        "depth image must be single-channel 16-bit unsigned or 32-bit float, got type " +
        std::to_string(depth.type()));
}

// The circle through every lifted sample (they are spread evenly along the boundary), kept only
// if they all lie near it.
CircleFit fit_rim_circle(const std::vector<Eigen::Vector3d>& curve, const Eigen::Vector3d& origin,
                         const Eigen::Vector3d& normal, const DepthOptions& options) {
  // The algebraic fit first: a rim far from circular (a box) is told apart without iterating.
  CircleFit circle = fit_circle_in_plane(curve, origin, normal, 0);
  if (!circle.found || circle.rms > 2.0 * options.circle_max_relative_rms * circle.radius) {
    circle.found = false;
    return circle;
  }
  circle = fit_circle_in_plane(curve, origin, normal);
  circle.found = circle.found && circle.rms <= options.circle_max_relative_rms * circle.radius;
  return circle;
}

}  // namespace

Boundary3d lift_boundary_to_3d(const Polygon& boundary, const cv::Mat& depth,
                               const PinholeIntrinsics& camera, const DepthOptions& options) {
  options.check();
  camera.check();
  check_depth_image(depth);
  Boundary3d result;
  const std::vector<BoundarySample> samples = sample_boundary_inward(boundary, options.sample_step);
  const std::size_t n = samples.size();
  result.n_samples = static_cast<int>(n);
  if (n == 0) return result;

  std::vector<SurfaceDepth> surfaces(n);
  std::vector<double> z(n);
  std::vector<DepthPixel> scratch;
  for (std::size_t i = 0; i < n; ++i) {
    surfaces[i] = nearest_surface_depth(depth, samples[i], options, &scratch);
    z[i] = surfaces[i].z;
  }
  reject_curve_outliers(options, &z);

  std::vector<Eigen::Vector3d> rays(n);
  result.samples.resize(n);
  result.points.assign(n, kNan);
  for (std::size_t i = 0; i < n; ++i) {
    result.samples[i] = samples[i].pixel;
    rays[i] = pixel_ray(camera, samples[i].pixel);
    if (z[i] > 0.0) result.points[i] = z[i] * pixel_ray(camera, surfaces[i].pixel);
  }

  const PlaneFit plane = fit_plane_robust(result.points, options);
  result.curve.assign(n, kNan);
  if (!plane.found) return result;
  for (std::size_t i = 0; i < n; ++i)
    if (!plane.inlier[i]) result.points[i] = kNan;
  result.n_valid = plane.n_inliers;
  result.normal = plane.normal;
  result.plane_offset = plane.offset;
  result.rms = plane.rms;
  for (std::size_t i = 0; i < n; ++i) intersect_ray_with_plane(plane, rays[i], &result.curve[i]);
  result.centroid = closed_curve_centroid(result.curve);
  result.circle = fit_rim_circle(result.curve, result.centroid, plane.normal, options);
  result.valid = result.n_valid >= options.min_valid_points &&
                 result.n_valid >= options.min_valid_fraction * static_cast<double>(n) &&
                 result.centroid.allFinite();
  return result;
}

}  // namespace scbt
