#include "scbt/eval/alignment_error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "scbt/geometry/polygon_io.h"

namespace scbt {
namespace {

// Boundary pixels are 0 on a 255 background, which is what distanceTransform measures from.
cv::Mat draw_boundary(const Polygon& polygon, cv::Size canvas) {
  cv::Mat image(canvas, CV_8U, cv::Scalar(255));
  std::vector<cv::Point> points;
  points.reserve(polygon.size());
  for (const Point& p : polygon) {
    // Clamp far-away coordinates so the integer conversion cannot overflow; drawing clips them.
    const double x = std::clamp(p.x, -1e6, 1e6), y = std::clamp(p.y, -1e6, 1e6);
    points.emplace_back(cvRound(x), cvRound(y));
  }
  cv::polylines(image, points, true, cv::Scalar(0), 1, cv::LINE_8);
  return image;
}

// The canvas part that can hold pixels of either boundary: their vertices' bounding box, grown by
// a pixel for rounding, clipped to the canvas (empty when both lie outside).
cv::Rect drawn_region(const Polygon& a, const Polygon& b, cv::Size canvas) {
  double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9;
  for (const Polygon* polygon : {&a, &b}) {
    for (const Point& p : *polygon) {
      x0 = std::min(x0, p.x);
      y0 = std::min(y0, p.y);
      x1 = std::max(x1, p.x);
      y1 = std::max(y1, p.y);
    }
  }
  const int left = static_cast<int>(std::clamp(std::floor(x0) - 1, 0.0, double(canvas.width)));
  const int top = static_cast<int>(std::clamp(std::floor(y0) - 1, 0.0, double(canvas.height)));
  const int right = static_cast<int>(std::clamp(std::ceil(x1) + 2, 0.0, double(canvas.width)));
  const int bottom = static_cast<int>(std::clamp(std::ceil(y1) + 2, 0.0, double(canvas.height)));
  return cv::Rect(left, top, std::max(0, right - left), std::max(0, bottom - top));
}

// Mean of `distance` over the boundary pixels of `boundary`; NaN when it has none.
double mean_over_boundary(const cv::Mat& boundary, const cv::Mat& distance) {
  double sum = 0.0;
  long count = 0;
  for (int y = 0; y < boundary.rows; ++y) {
    const uchar* b = boundary.ptr<uchar>(y);
    const float* d = distance.ptr<float>(y);
    for (int x = 0; x < boundary.cols; ++x) {
      if (b[x] == 0) {
        sum += d[x];
        ++count;
      }
    }
  }
  return count > 0 ? sum / static_cast<double>(count) : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

bool is_scorable_polygon(const Polygon& polygon) {
  for (const Point& p : polygon) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
  }
  return count_distinct_points(polygon) >= 3 && area(polygon) > 0.0;
}

double alignment_error(const Polygon& tracked, const Polygon& truth, cv::Size canvas) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  if (!is_scorable_polygon(tracked) || !is_scorable_polygon(truth)) return kInfinity;
  // Both boundaries lie inside the canvas-clipped union of their bounding boxes, so the distance
  // transforms (exact, DIST_MASK_PRECISE) restricted to it give the same values: the nearest
  // boundary pixel of any pixel is inside. This only saves time for boundaries smaller than the
  // canvas; the drawing itself is done on the whole canvas so that clipping is unchanged.
  const cv::Rect roi = drawn_region(tracked, truth, canvas);
  if (roi.empty()) return kInfinity;
  const cv::Mat tracked_image = draw_boundary(tracked, canvas)(roi);
  const cv::Mat truth_image = draw_boundary(truth, canvas)(roi);
  cv::Mat tracked_distance, truth_distance;
  cv::distanceTransform(tracked_image, tracked_distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  cv::distanceTransform(truth_image, truth_distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  const double tracked_to_truth = mean_over_boundary(tracked_image, truth_distance);
  const double truth_to_tracked = mean_over_boundary(truth_image, tracked_distance);
  if (std::isnan(tracked_to_truth) || std::isnan(truth_to_tracked)) return kInfinity;
  return std::max(tracked_to_truth, truth_to_tracked);
}

double success_rate(const std::vector<double>& errors, double threshold) {
  if (errors.empty()) return 0.0;
  size_t below = 0;
  for (double e : errors) below += e < threshold ? 1 : 0;
  return static_cast<double>(below) / static_cast<double>(errors.size());
}

double alignment_error_of_line(const std::string& line, const Polygon& truth, cv::Size canvas,
                               std::string* note) {
  if (note) note->clear();
  Polygon tracked;
  std::string error;
  if (!try_parse_polygon_line(line, &tracked, &error)) {
    if (note) *note = error;
    return std::numeric_limits<double>::infinity();
  }
  if (!is_scorable_polygon(tracked)) {
    if (note) *note = "degenerate polygon (fewer than 3 distinct points or no area)";
    return std::numeric_limits<double>::infinity();
  }
  const double error_al = alignment_error(tracked, truth, canvas);
  if (note && !std::isfinite(error_al))
    *note = "no boundary pixel on the canvas, or degenerate truth";
  return error_al;
}

}  // namespace scbt
