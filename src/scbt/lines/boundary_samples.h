// Reading the grey levels around a closed boundary, shared by the measurements of its edges
// (boundary_edge_strength, estimate_edge_blur).
#pragma once

#include <algorithm>
#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <opencv2/core/types.hpp>

#include "scbt/geometry/polygon.h"

namespace scbt {

// Bilinear sample of an 8-bit grey image (clamped to the border).
inline double bilinear_grey(const cv::Mat& gray, double x, double y) {
  x = std::clamp(x, 0.0, gray.cols - 1.001);
  y = std::clamp(y, 0.0, gray.rows - 1.001);
  const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
  const double fx = x - x0, fy = y - y0;
  const std::uint8_t* r0 = gray.ptr<std::uint8_t>(y0);
  const std::uint8_t* r1 = gray.ptr<std::uint8_t>(y0 + 1);
  const double top = r0[x0] + fx * (r0[x0 + 1] - r0[x0]);
  const double bottom = r1[x0] + fx * (r1[x0 + 1] - r1[x0]);
  return top + fy * (bottom - top);
}

// Calls visit(point, tangent, normal) at `samples` points spaced evenly along the closed
// `boundary` (the first half a spacing from vertex 0), in the coordinates of an image whose
// top-left corner is `offset`; `tangent` is the unit direction of the boundary there, `normal`
// its left normal (-t.y, t.x).
template <class Visit>
void for_each_boundary_sample(const Polygon& boundary, cv::Point offset, int samples,
                              Visit&& visit) {
  const size_t n = boundary.size();
  const double length = perimeter(boundary);
  if (n < 2 || samples < 1 || !(length > 0.0)) return;
  const double step = length / samples;
  double along = 0.5 * step;  // arc length of the next sample
  double edge_start = 0.0;
  int visited = 0;
  for (size_t i = 0; i < n && visited < samples; ++i) {
    const Point a = boundary[i] - Point(offset.x, offset.y);
    const Point b = boundary[(i + 1) % n] - Point(offset.x, offset.y);
    const double edge = cv::norm(b - a);
    if (edge <= 0.0) continue;
    const Point t = (b - a) * (1.0 / edge);
    const Point normal(-t.y, t.x);
    for (; along < edge_start + edge && visited < samples; along += step, ++visited) {
      visit(a + t * (along - edge_start), t, normal);
    }
    edge_start += edge;
  }
}

}  // namespace scbt
