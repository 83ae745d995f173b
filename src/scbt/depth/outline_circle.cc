#include "scbt/depth/outline_circle.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

namespace scbt {
namespace {

// Direct least-squares ellipse fit (Fitzgibbon et al. 1999, with Halir and Flusser's 1998
// split of the scatter matrix for numerical stability) on points centred and scaled to unit
// spread, so that the scatter matrix is well conditioned. Returns the conic matrix in the
// original coordinates, or false.
bool fit_ellipse(const std::vector<Eigen::Vector2d>& points, Eigen::Matrix3d* conic) {
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  double spread = 0.0;
  for (const Eigen::Vector2d& p : points) spread += (p - mean).squaredNorm();
  spread = std::sqrt(spread / static_cast<double>(points.size()));
  if (!(spread > 0.0)) return false;
  const double scale = 1.0 / spread;

  Eigen::Matrix3d s1 = Eigen::Matrix3d::Zero(), s2 = Eigen::Matrix3d::Zero(),
                  s3 = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector2d& p : points) {
    const Eigen::Vector2d q = (p - mean) * scale;
    const Eigen::Vector3d quadratic(q.x() * q.x(), q.x() * q.y(), q.y() * q.y());
    const Eigen::Vector3d linear(q.x(), q.y(), 1.0);
    s1 += quadratic * quadratic.transpose();
    s2 += quadratic * linear.transpose();
    s3 += linear * linear.transpose();
  }
  const Eigen::FullPivLU<Eigen::Matrix3d> s3_lu(s3);
  if (!s3_lu.isInvertible()) return false;
  const Eigen::Matrix3d t = -s3_lu.solve(s2.transpose());  // linear part = t * quadratic part
  const Eigen::Matrix3d m = s1 + s2 * t;
  // Premultiplied by the inverse of the constraint matrix [0 0 2; 0 -1 0; 2 0 0].
  Eigen::Matrix3d reduced;
  reduced.row(0) = m.row(2) / 2.0;
  reduced.row(1) = -m.row(1);
  reduced.row(2) = m.row(0) / 2.0;
  const Eigen::EigenSolver<Eigen::Matrix3d> solver(reduced);
  int chosen = -1;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d v = solver.eigenvectors().col(k).real();
    if (4.0 * v(0) * v(2) - v(1) * v(1) > 0.0) chosen = k;  // the ellipse's eigenvector
  }
  if (chosen < 0) return false;
  const Eigen::Vector3d quadratic = solver.eigenvectors().col(chosen).real();
  const Eigen::Vector3d linear = t * quadratic;
  // The conic in the scaled coordinates, then back: q = S (p - mean).
  Eigen::Matrix3d scaled;
  scaled << quadratic(0), quadratic(1) / 2, linear(0) / 2,  //
      quadratic(1) / 2, quadratic(2), linear(1) / 2,        //
      linear(0) / 2, linear(1) / 2, linear(2);
  Eigen::Matrix3d to_scaled = Eigen::Matrix3d::Identity();
  to_scaled.topLeftCorner<2, 2>() *= scale;
  to_scaled.topRightCorner<2, 1>() = -scale * mean;
  *conic = to_scaled.transpose() * scaled * to_scaled;
  return conic->allFinite();
}

}  // namespace

OutlineNormals circle_normals_from_outline(const std::vector<Eigen::Vector3d>& rays) {
  OutlineNormals result;
  std::vector<Eigen::Vector2d> points;
  points.reserve(rays.size());
  for (const Eigen::Vector3d& ray : rays)
    if (ray.allFinite() && ray.z() > 0.0) points.emplace_back(ray.x() / ray.z(), ray.y() / ray.z());
  if (points.size() < 6) return result;
  Eigen::Matrix3d cone;
  if (!fit_ellipse(points, &cone)) return result;
  // The cone X^T C X = 0 in its eigenbasis is l1 x^2 + l2 y^2 + l3 z^2 = 0 (l1 >= l2 >= l3).
  // On it (l1 - l2) x^2 - (l2 - l3) z^2 = -l2 |X|^2, whose left side factors into two planes:
  // a plane parallel to either meets the cone on a sphere, so in a circle.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(cone);
  const Eigen::Vector3d l = solver.eigenvalues();  // ascending
  const Eigen::Matrix3d v = solver.eigenvectors();
  const double l1 = l(2), l2 = l(1), l3 = l(0);
  if (!(l1 > 0.0 && l3 < 0.0)) return result;  // not a real cone
  const double a = std::sqrt(std::max(0.0, (l1 - l2) / (l1 - l3)));
  const double c = std::sqrt(std::max(0.0, (l2 - l3) / (l1 - l3)));
  for (int k = 0; k < 2; ++k) {
    Eigen::Vector3d normal = a * v.col(2) + (k == 0 ? c : -c) * v.col(0);
    normal.normalize();
    // Towards the camera: the rim lies in front of it, along its mean ray.
    Eigen::Vector3d towards = Eigen::Vector3d::Zero();
    for (const Eigen::Vector2d& p : points) towards += Eigen::Vector3d(p.x(), p.y(), 1.0);
    if (normal.dot(towards) > 0.0) normal = -normal;
    result.normals[k] = normal;
  }
  result.found = result.normals[0].allFinite() && result.normals[1].allFinite();
  return result;
}

}  // namespace scbt
