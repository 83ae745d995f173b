#include "scbt/eval/alignment_error.h"

#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

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
  const cv::Mat tracked_image = draw_boundary(tracked, canvas);
  const cv::Mat truth_image = draw_boundary(truth, canvas);
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

}  // namespace scbt
