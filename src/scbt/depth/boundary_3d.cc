#include "scbt/depth/boundary_3d.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "scbt/depth/boundary_samples.h"
#include "scbt/depth/curve_centroid.h"
#include "scbt/depth/curve_outliers.h"
#include "scbt/depth/depth_window.h"
#include "scbt/depth/outline_circle.h"
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

// The depth plane turned to the outline's circle normal nearest it, at the distance its inlier
// points give, each weighted by 1 / sigma(z)^2 ~ z^-4; false (plane unchanged) when the outline
// is not an ellipse or its normals are both farther than options.outline_normal_max_angle.
bool turn_plane_to_outline(const std::vector<Eigen::Vector3d>& rays,
                           const std::vector<Eigen::Vector3d>& points, const DepthOptions& options,
                           PlaneFit* plane) {
  if (!(options.outline_normal_max_angle > 0.0)) return false;
  const OutlineNormals outline = circle_normals_from_outline(rays);
  if (!outline.found) return false;
  const Eigen::Vector3d& normal =
      outline.normals[0].dot(plane->normal) >= outline.normals[1].dot(plane->normal)
          ? outline.normals[0]
          : outline.normals[1];
  const double cos_limit =
      std::cos(options.outline_normal_max_angle * 3.14159265358979323846 / 180.0);
  if (!(normal.dot(plane->normal) >= cos_limit)) return false;
  double weighted = 0.0, weights = 0.0;
  for (const Eigen::Vector3d& p : points) {
    if (!p.allFinite()) continue;
    const double w = 1.0 / (p.z() * p.z() * p.z() * p.z());
    weighted += w * normal.dot(p);
    weights += w;
  }
  if (!(weights > 0.0)) return false;
  plane->normal = normal;
  plane->offset = weighted / weights;
  double sum_sq = 0.0;
  for (const Eigen::Vector3d& p : points) {
    if (!p.allFinite()) continue;
    const double distance = normal.dot(p) - plane->offset;
    sum_sq += distance * distance;
  }
  plane->rms = std::sqrt(sum_sq / plane->n_inliers);
  return true;
}

}  // namespace

Boundary3d lift_boundary_to_3d(const Polygon& boundary, const cv::Mat& depth,
                               const PinholeIntrinsics& camera, const DepthOptions& options) {
  options.check();
  camera.check();
  check_depth_image(depth);
  Boundary3d result;
  // Only where a sample's window reaches the depth image can depth be read: along the edges,
  // nowhere else (the vertices outside still close the curve, whose parts there the plane gives).
  const double reach = options.window_offset + options.window_length + options.window_half_width;
  const SampleRegion region{-reach - 1.0, -reach - 1.0, depth.cols + reach, depth.rows + reach};
  const std::vector<BoundarySample> samples =
      sample_boundary_inward(boundary, options.sample_step, region);
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

  PlaneFit plane = fit_plane_robust(result.points, options);
  result.curve.assign(n, kNan);
  if (!plane.found) return result;
  for (std::size_t i = 0; i < n; ++i)
    if (!plane.inlier[i]) result.points[i] = kNan;
  result.n_valid = plane.n_inliers;
  for (std::size_t i = 0; i < n; ++i) intersect_ray_with_plane(plane, rays[i], &result.curve[i]);
  result.centroid = closed_curve_centroid(result.curve);
  // A rim that is roughly circular by the algebraic fit (fit_rim_circle's screen) takes its
  // normal from the outline before the circle is fitted.
  const CircleFit screen = fit_circle_in_plane(result.curve, result.centroid, plane.normal, 0);
  const bool roughly_circular =
      screen.found && screen.rms <= 2.0 * options.circle_max_relative_rms * screen.radius;
  if (roughly_circular && turn_plane_to_outline(rays, result.points, options, &plane)) {
    for (std::size_t i = 0; i < n; ++i) intersect_ray_with_plane(plane, rays[i], &result.curve[i]);
    result.centroid = closed_curve_centroid(result.curve);
  }
  if (roughly_circular)
    result.circle = fit_rim_circle(result.curve, result.centroid, plane.normal, options);
  result.normal = plane.normal;
  result.plane_offset = plane.offset;
  result.rms = plane.rms;
  result.valid = result.n_valid >= options.min_valid_points &&
                 result.n_valid >= options.min_valid_fraction * static_cast<double>(n) &&
                 result.centroid.allFinite();
  return result;
}

}  // namespace scbt
