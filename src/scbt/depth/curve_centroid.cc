#include "scbt/depth/curve_centroid.h"

#include <limits>

namespace scbt {

Eigen::Vector3d closed_curve_centroid(const std::vector<Eigen::Vector3d>& points) {
  std::vector<const Eigen::Vector3d*> curve;
  curve.reserve(points.size());
  for (const Eigen::Vector3d& p : points)
    if (p.allFinite()) curve.push_back(&p);
  if (curve.empty()) return Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
  double length = 0.0;
  for (std::size_t i = 0; i < curve.size(); ++i) {
    const Eigen::Vector3d& a = *curve[i];
    const Eigen::Vector3d& b = *curve[(i + 1) % curve.size()];
    const double edge = (b - a).norm();
    weighted += edge * 0.5 * (a + b);
    length += edge;
  }
  return length > 0.0 ? Eigen::Vector3d(weighted / length) : *curve.front();
}

}  // namespace scbt
