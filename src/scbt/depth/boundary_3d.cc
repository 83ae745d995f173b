#include "scbt/depth/boundary_3d.h"

#include <algorithm>
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

// The centre of the shortest interval holding half of `values` (the "shorth"; sorts them): for
// noise alone the middle like a mean, but a one-sided tail (mixed pixels, all farther than the
// rim) moves it far less than it moves a mean.
double shortest_half_centre(std::vector<double>* values) {
  std::sort(values->begin(), values->end());
  const std::vector<double>& v = *values;
  const std::size_t half = v.size() / 2;
  std::size_t best = 0;
  for (std::size_t i = 1; i + half < v.size(); ++i)
    if (v[i + half] - v[i] < v[best + half] - v[best]) best = i;
  return 0.5 * (v[best] + v[best + half]);
}

// The depth plane turned to the outline's circle normal nearest it, at the distance its inlier
// points give (the centre of their shortest half along the normal); false (plane unchanged) when
// the outline is not an ellipse or its normals are both farther than
// options.outline_normal_max_angle.
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
  std::vector<double> distances;
  for (const Eigen::Vector3d& p : points)
    if (p.allFinite()) distances.push_back(normal.dot(p));
  if (distances.size() < 2) return false;
  plane->normal = normal;
  plane->offset = shortest_half_centre(&distances);
  double sum_sq = 0.0;
  for (const Eigen::Vector3d& p : points) {
    if (!p.allFinite()) continue;
    const double distance = normal.dot(p) - plane->offset;
    sum_sq += distance * distance;
  }
  plane->rms = std::sqrt(sum_sq / plane->n_inliers);
  return true;
}

// The window row every sample's depth is read from: the one whose depth, where a sample has it
// on its surface, is on average over the plane's inliers nearest the camera (samples without
// it count as their first row). The first row straddles the object's edge (mixed pixels read
// between the object and the background behind it), a row too far in can be past a thin lip on
// a bowl's inner wall: both read farther than the rim, and noise averaged over the whole
// boundary hardly moves the comparison. -1 when no row reads nearer than every sample's first.
int nearest_reading_row(const std::vector<SurfaceDepth>& surfaces,
                        const std::vector<Eigen::Vector3d>& first_points, const PlaneFit& plane,
                        const PinholeIntrinsics& camera, const DepthOptions& options) {
  int best = -1;
  double best_gain = 0.0;
  for (int row = 0; row < options.window_length; ++row) {
    double gain = 0.0;  // towards the camera, summed over the inliers
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
      const RowDepth& depth = surfaces[i].rows[row];
      if (!plane.inlier[i] || !(depth.z > 0.0)) continue;
      gain += plane.normal.dot(depth.z * pixel_ray(camera, depth.pixel) - first_points[i]);
    }
    if (gain > best_gain) best = row, best_gain = gain;
  }
  return best;
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
  std::vector<DepthPixel> scratch;
  for (std::size_t i = 0; i < n; ++i)
    surfaces[i] = nearest_surface_depth(depth, samples[i], options, &scratch);

  std::vector<Eigen::Vector3d> rays(n);
  result.samples.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    result.samples[i] = samples[i].pixel;
    rays[i] = pixel_ray(camera, samples[i].pixel);
  }
  // Each sample's surface point, read from window row `row` (-1: its first row on the surface;
  // a sample without that row keeps its first), after the curve's outliers are dropped.
  std::vector<double> z(n);
  auto lift_points = [&](int row) {
    for (std::size_t i = 0; i < n; ++i)
      z[i] = row >= 0 && surfaces[i].rows[row].z > 0.0 ? surfaces[i].rows[row].z : surfaces[i].z;
    reject_curve_outliers(options, &z);
    result.points.assign(n, kNan);
    for (std::size_t i = 0; i < n; ++i) {
      if (!(z[i] > 0.0)) continue;
      const bool own = row >= 0 && surfaces[i].rows[row].z > 0.0;
      result.points[i] =
          z[i] * pixel_ray(camera, own ? surfaces[i].rows[row].pixel : surfaces[i].pixel);
    }
  };
  lift_points(-1);
  PlaneFit plane = fit_plane_robust(result.points, options);
  if (plane.found) {
    const int row = nearest_reading_row(surfaces, result.points, plane, camera, options);
    if (row >= 0) {
      const std::vector<Eigen::Vector3d> first_points = result.points;
      lift_points(row);
      PlaneFit refit = fit_plane_robust(result.points, options);
      if (refit.found)
        plane = std::move(refit);
      else
        result.points = first_points;
    }
  }
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
