#include "scbt/render/rim_overlay.h"

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>

namespace scbt {
namespace {

const cv::Scalar kCentroid(255, 0, 255);  // magenta: apart from the boundary's yellow
const cv::Scalar kNormal(255, 255, 0);
const cv::Scalar kCircle(0, 200, 0);

bool to_pixel(const PinholeIntrinsics& camera, const Eigen::Vector3d& point, cv::Point* pixel) {
  if (!(point.z() > 1e-3) || !point.allFinite()) return false;
  const Point p = project_point(camera, point);
  if (!(std::abs(p.x) < 1e6 && std::abs(p.y) < 1e6)) return false;
  *pixel = cv::Point(cvRound(p.x), cvRound(p.y));
  return true;
}

}  // namespace

void draw_rim_3d(cv::Mat* image, const Boundary3d& rim, const PinholeIntrinsics& camera,
                 double normal_length) {
  char text[64];
  const cv::Point corner(8, image->rows - 10);
  if (!rim.valid) {
    std::snprintf(text, sizeof text, "no 3-D (%d/%d depths)", rim.n_valid, rim.n_samples);
    cv::putText(*image, text, corner, cv::FONT_HERSHEY_SIMPLEX, 0.5, kCentroid, 1, cv::LINE_AA);
    return;
  }
  if (rim.circle.found) {
    const Eigen::Vector3d u = rim.circle.normal.unitOrthogonal();
    const Eigen::Vector3d v = rim.circle.normal.cross(u);
    std::vector<cv::Point> outline;
    for (int i = 0; i < 72; ++i) {
      const double angle = 2.0 * M_PI * i / 72;
      cv::Point pixel;
      if (to_pixel(
              camera,
              rim.circle.centre + rim.circle.radius * (std::cos(angle) * u + std::sin(angle) * v),
              &pixel))
        outline.push_back(pixel);
    }
    if (outline.size() > 2) cv::polylines(*image, outline, true, kCircle, 1, cv::LINE_AA);
  }
  cv::Point centre, tip;
  if (to_pixel(camera, rim.centroid, &centre)) {
    cv::drawMarker(*image, centre, kCentroid, cv::MARKER_CROSS, 14, 2, cv::LINE_AA);
    if (to_pixel(camera, rim.centroid + normal_length * rim.normal, &tip))
      cv::arrowedLine(*image, centre, tip, kNormal, 2, cv::LINE_AA, 0, 0.2);
  }
  std::snprintf(text, sizeof text, "z %.3f m  (%d/%d depths)", rim.centroid.z(), rim.n_valid,
                rim.n_samples);
  cv::putText(*image, text, corner, cv::FONT_HERSHEY_SIMPLEX, 0.5, kCentroid, 1, cv::LINE_AA);
}

}  // namespace scbt
