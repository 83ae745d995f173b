#include "scbt/depth/circle_fit.h"

#include <Eigen/Dense>
#include <cmath>

namespace scbt {
namespace {

// Two unit vectors spanning the plane of `normal`.
void plane_basis(const Eigen::Vector3d& normal, Eigen::Vector3d* u, Eigen::Vector3d* v) {
  const Eigen::Vector3d helper =
      std::abs(normal.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  *u = normal.cross(helper).normalized();
  *v = normal.cross(*u);
}

}  // namespace

CircleFit fit_circle_in_plane(const std::vector<Eigen::Vector3d>& points,
                              const Eigen::Vector3d& origin, const Eigen::Vector3d& normal,
                              int iterations) {
  CircleFit circle;
  Eigen::Vector3d u, v;
  plane_basis(normal, &u, &v);
  std::vector<Eigen::Vector2d> flat;
  flat.reserve(points.size());
  for (const Eigen::Vector3d& p : points)
    if (p.allFinite()) flat.emplace_back(u.dot(p - origin), v.dot(p - origin));
  if (flat.size() < 3) return circle;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& q : flat) mean += q;
  mean /= static_cast<double>(flat.size());
  Eigen::Matrix2d spread = Eigen::Matrix2d::Zero();
  for (const Eigen::Vector2d& q : flat) spread += (q - mean) * (q - mean).transpose();
  if (!(spread.determinant() > 1e-12 * spread.trace() * spread.trace())) return circle;  // a line

  // Kasa: x^2 + y^2 + D x + E y + F = 0 in least squares.
  Eigen::Matrix3d normal_matrix = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  for (const Eigen::Vector2d& q : flat) {
    const Eigen::Vector3d row(q.x(), q.y(), 1.0);
    normal_matrix += row * row.transpose();
    rhs -= row * q.squaredNorm();
  }
  const Eigen::Vector3d def = normal_matrix.ldlt().solve(rhs);
  Eigen::Vector2d centre(-0.5 * def(0), -0.5 * def(1));
  const double radius_sq = centre.squaredNorm() - def(2);
  if (!def.allFinite() || !(radius_sq > 0.0)) return circle;
  double radius = std::sqrt(radius_sq);

  // Gauss-Newton on r_i = |q_i - c| - r.
  for (int iteration = 0; iteration < iterations; ++iteration) {
    Eigen::Matrix3d jtj = Eigen::Matrix3d::Zero();
    Eigen::Vector3d jtr = Eigen::Vector3d::Zero();
    for (const Eigen::Vector2d& q : flat) {
      const Eigen::Vector2d d = q - centre;
      const double distance = d.norm();
      if (distance < 1e-12) continue;
      const Eigen::Vector3d jacobian(-d.x() / distance, -d.y() / distance, -1.0);
      jtj += jacobian * jacobian.transpose();
      jtr += jacobian * (distance - radius);
    }
    const Eigen::Vector3d step = jtj.ldlt().solve(-jtr);
    if (!step.allFinite()) break;
    centre += step.head<2>();
    radius += step(2);
    if (step.norm() < 1e-12 * (1.0 + radius)) break;
  }
  if (!(radius > 0.0) || !centre.allFinite()) return circle;
  circle.found = true;
  circle.centre = origin + centre.x() * u + centre.y() * v;
  circle.normal = normal;
  circle.radius = radius;
  circle.rms = circle_rms(circle, points);
  return circle;
}

double circle_rms(const CircleFit& circle, const std::vector<Eigen::Vector3d>& points) {
  double sum_sq = 0.0;
  int count = 0;
  for (const Eigen::Vector3d& p : points) {
    if (!p.allFinite()) continue;
    Eigen::Vector3d d = p - circle.centre;
    d -= circle.normal.dot(d) * circle.normal;
    const double error = d.norm() - circle.radius;
    sum_sq += error * error;
    ++count;
  }
  return count ? std::sqrt(sum_sq / count) : 0.0;
}

}  // namespace scbt
