#include "scbt/depth/plane_fit.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "scbt/depth/depth_window.h"

namespace scbt {
namespace {

bool finite(const Eigen::Vector3d& p) { return p.allFinite(); }

// Least-squares plane through the points flagged in `use`; false when they are too few or
// (nearly) collinear.
bool fit_plane(const std::vector<Eigen::Vector3d>& points, const std::vector<bool>& use,
               Eigen::Vector3d* normal, double* offset) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  int count = 0;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (use[i]) mean += points[i], ++count;
  if (count < 3) return false;
  mean /= count;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < points.size(); ++i)
    if (use[i]) covariance += (points[i] - mean) * (points[i] - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  const Eigen::Vector3d eigenvalues = solver.eigenvalues();  // ascending
  if (!(eigenvalues(1) > 1e-12 * std::max(eigenvalues(2), 1e-300))) return false;
  *normal = solver.eigenvectors().col(0).normalized();
  if (normal->dot(mean) > 0.0) *normal = -*normal;  // towards the camera at the origin
  *offset = normal->dot(mean);
  return true;
}

// The start of the robust fit: of planes through evenly spaced triples of the points (a third
// of the curve apart, so well conditioned on a rim), the one with the least median distance
// (least median of squares, Rousseeuw 1984): right even when a coherent stretch of the rim --
// say its near side, where a thin lip is all mixed pixels -- is wrong.
bool least_median_plane(const std::vector<Eigen::Vector3d>& points,
                        const std::vector<std::size_t>& order, Eigen::Vector3d* normal,
                        double* offset) {
  const std::size_t m = order.size();
  if (m < 6) return false;
  constexpr std::size_t kTriples = 24;
  std::vector<double> distances(m);
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < kTriples; ++k) {
    const std::size_t i = k * m / kTriples;
    const Eigen::Vector3d& a = points[order[i]];
    const Eigen::Vector3d& b = points[order[(i + m / 3) % m]];
    const Eigen::Vector3d& c = points[order[(i + 2 * m / 3) % m]];
    Eigen::Vector3d candidate = (b - a).cross(c - a);
    if (!(candidate.norm() > 1e-12)) continue;
    candidate.normalize();
    for (std::size_t j = 0; j < m; ++j)
      distances[j] = std::abs(candidate.dot(points[order[j]] - a));
    auto middle = distances.begin() + m / 2;
    std::nth_element(distances.begin(), middle, distances.end());
    if (*middle < best) {
      best = *middle;
      *normal = candidate.dot(a) > 0.0 ? -candidate : candidate;
      *offset = normal->dot(a);
    }
  }
  return std::isfinite(best);
}

}  // namespace

PlaneFit fit_plane_robust(const std::vector<Eigen::Vector3d>& points, const DepthOptions& options) {
  PlaneFit fit;
  const std::size_t n = points.size();
  std::vector<std::size_t> finite_points;
  for (std::size_t i = 0; i < n; ++i)
    if (finite(points[i])) finite_points.push_back(i);
  std::vector<bool> use(n, false);
  for (std::size_t i : finite_points) use[i] = true;
  Eigen::Vector3d normal;
  double offset = 0.0;
  if (!least_median_plane(points, finite_points, &normal, &offset) &&
      !fit_plane(points, use, &normal, &offset))
    return fit;
  std::vector<double> distances;
  for (int iteration = 0; iteration < options.plane_iterations; ++iteration) {
    distances.clear();
    for (std::size_t i : finite_points)
      distances.push_back(std::abs(normal.dot(points[i]) - offset));
    auto middle = distances.begin() + distances.size() / 2;
    std::nth_element(distances.begin(), middle, distances.end());
    const double spread = 3.0 * 1.4826 * *middle;
    bool changed = false;
    for (std::size_t i : finite_points) {
      const double distance = std::abs(normal.dot(points[i]) - offset);
      const bool keep = distance <= std::max(surface_tolerance(options, points[i].z()), spread);
      changed = changed || keep != use[i];
      use[i] = keep;
    }
    if (iteration > 0 && !changed) break;
    if (!fit_plane(points, use, &normal, &offset)) return fit;
  }
  double sum_sq = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!use[i]) continue;
    const double distance = normal.dot(points[i]) - offset;
    sum_sq += distance * distance;
    ++fit.n_inliers;
  }
  if (fit.n_inliers < 3) return fit;
  fit.found = true;
  fit.normal = normal;
  fit.offset = offset;
  fit.rms = std::sqrt(sum_sq / fit.n_inliers);
  fit.inlier = std::move(use);
  return fit;
}

bool intersect_ray_with_plane(const PlaneFit& plane, const Eigen::Vector3d& ray,
                              Eigen::Vector3d* point) {
  const double along = plane.normal.dot(ray);
  if (std::abs(along) < 1e-9) return false;
  const double z = plane.offset / along;
  if (!(z > 0.0)) return false;
  *point = z * ray;
  return true;
}

}  // namespace scbt
