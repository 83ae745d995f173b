// Reading the grey levels around a closed boundary, shared by the measurements of its edges
// (boundary_edge_strength, estimate_edge_blur).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <opencv2/core/types.hpp>

#include "scbt/geometry/polygon.h"

namespace scbt {

// The grey levels 0..255 as doubles, read by GreySampler rather than converted one by one.
struct GreyLevels {
  double value[256];
  constexpr GreyLevels() : value() {
    for (int v = 0; v < 256; ++v) value[v] = v;
  }
};
inline constexpr GreyLevels kGreyLevels{};

// Bilinear samples of an 8-bit grey image, its rows and size read out of the cv::Mat once: the
// measurements read thousands of points per frame.
class GreySampler {
 public:
  explicit GreySampler(const cv::Mat& gray)
      : data_(gray.data),
        step_(gray.step[0]),
        max_x_(gray.cols - 1.001),
        max_y_(gray.rows - 1.001) {}

  // The sample at (x, y), clamped to the border.
  double clamped(double x, double y) const {
    return inside(std::clamp(x, 0.0, max_x_), std::clamp(y, 0.0, max_y_));
  }
  // The same for a point the clamp leaves alone: x in [0, cols - 1.001], y in [0, rows - 1.001].
  double inside(double x, double y) const {
    const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
    const double fx = x - x0, fy = y - y0;
    const std::uint8_t* r0 = data_ + static_cast<size_t>(y0) * step_ + x0;
    const std::uint8_t* r1 = r0 + step_;
    // Levels read from a table rather than converted: their differences are exact in double, so
    // each sample is what integer differences gave.
    const double* level = kGreyLevels.value;
    const double a = level[r0[0]], b = level[r0[1]], c = level[r1[0]], d = level[r1[1]];
    const double top = a + fx * (b - a);
    const double bottom = c + fx * (d - c);
    return top + fy * (bottom - top);
  }
  // Whether every point within `radius` of p is one the clamp leaves alone.
  bool holds_disc(Point p, double radius) const {
    return p.x >= radius && p.y >= radius && p.x + radius <= max_x_ && p.y + radius <= max_y_;
  }

 private:
  const std::uint8_t* data_;
  size_t step_;
  double max_x_, max_y_;
};

// Bilinear sample of an 8-bit grey image (clamped to the border).
inline double bilinear_grey(const cv::Mat& gray, double x, double y) {
  return GreySampler(gray).clamped(x, y);
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
