#include "scbt/peers/peer_common.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "scbt/geometry/polygon_io.h"
#include "scbt/tracker/tracker.h"

namespace scbt {

Polygon apply_homography(const cv::Mat& h, const Polygon& polygon) {
  Polygon out;
  out.reserve(polygon.size());
  for (const Point& p : polygon) {
    const double x = h.at<double>(0, 0) * p.x + h.at<double>(0, 1) * p.y + h.at<double>(0, 2);
    const double y = h.at<double>(1, 0) * p.x + h.at<double>(1, 1) * p.y + h.at<double>(1, 2);
    const double w = h.at<double>(2, 0) * p.x + h.at<double>(2, 1) * p.y + h.at<double>(2, 2);
    out.emplace_back(x / w, y / w);  // w == 0 gives inf/nan, rejected by plausible_update
  }
  return out;
}

bool plausible_update(const Polygon& candidate, double reference_area, const cv::Size& frame_size,
                      double max_area_factor) {
  if (candidate.size() < 3) return false;
  for (const Point& p : candidate) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
  }
  const double a = area(candidate);
  if (!(a > 0.0) || a > reference_area * max_area_factor || a * max_area_factor < reference_area) {
    return false;
  }
  if (count_distinct_points(candidate) < 3 || !is_simple(candidate)) return false;
  const Point c = centroid(candidate);
  const double mx = 0.5 * frame_size.width;
  const double my = 0.5 * frame_size.height;
  return c.x > -mx && c.y > -my && c.x < frame_size.width + mx && c.y < frame_size.height + my;
}

}  // namespace scbt
