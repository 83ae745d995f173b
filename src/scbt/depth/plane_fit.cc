#include "scbt/depth/plane_fit.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

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

}  // namespace

PlaneFit fit_plane_robust(const std::vector<Eigen::Vector3d>& points, const DepthOptions& options) {
  PlaneFit fit;
  const std::size_t n = points.size();
  std::vector<bool> use(n);
  for (std::size_t i = 0; i < n; ++i) use[i] = finite(points[i]);
  std::vector<double> distances;
  for (int iteration = 0; iteration < options.plane_iterations; ++iteration) {
    Eigen::Vector3d normal;
    double offset = 0.0;
    if (!fit_plane(points, use, &normal, &offset)) break;
    fit.found = true;
    fit.normal = normal;
    fit.offset = offset;
    distances.clear();
    for (std::size_t i = 0; i < n; ++i)
      if (use[i]) distances.push_back(std::abs(normal.dot(points[i]) - offset));
    auto middle = distances.begin() + distances.size() / 2;
    std::nth_element(distances.begin(), middle, distances.end());
    const double spread = 3.0 * 1.4826 * *middle;
    bool changed = false;
    for (std::size_t i = 0; i < n; ++i) {
      if (!finite(points[i])) continue;
      const double distance = std::abs(normal.dot(points[i]) - offset);
      const bool keep = distance <= std::max(surface_tolerance(options, points[i].z()), spread);
      changed = changed || keep != use[i];
      use[i] = keep;
    }
    if (!changed) break;
  }
  if (!fit.found) return fit;
  double sum_sq = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!use[i]) continue;
    const double distance = fit.normal.dot(points[i]) - fit.offset;
    sum_sq += distance * distance;
    ++fit.n_inliers;
  }
  if (fit.n_inliers < 3) {
    fit.found = false;
    return fit;
  }
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
