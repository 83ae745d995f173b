#include "scbt/tracker/confidence.h"

#include <algorithm>
#include <cmath>

#include "scbt/geometry/pixel_round.h"

namespace scbt {
namespace {

// Samples along the boundary for the edge support, and how far either side of it (pixels) the
// grey levels are compared: beyond EDLines' Gaussian (sigma 1), so a blurred step is seen whole.
constexpr int kEdgeSamples = 48;
constexpr double kSideOffset = 2.0;

}  // namespace

double ConfidenceModel::operator()(const BoundaryEvidence& e) const {
  const double z = bias + gap_share * e.gap_share + edge_support * e.edge_support +
                   shape_change * e.shape_change + jump * e.jump;
  return 1.0 / (1.0 + std::exp(-z));
}

EdgeSamples sample_edges(const Polygon& boundary, const cv::Mat& gray, cv::Point gray_origin,
                         double min_step) {
  EdgeSamples out;
  const size_t n = boundary.size();
  const double length = perimeter(boundary);
  if (n < 2 || !(length > 0.0) || gray.empty()) return out;
  // The left normal (-dy, dx) points inside when the shoelace area is positive.
  const bool left_inside = signed_area(boundary) > 0.0;
  int inside_sum = 0, inside_count = 0;
  const double step = length / kEdgeSamples;
  int supported = 0;
  size_t edge = 0;
  double edge_start = 0.0;
  double edge_length = cv::norm(boundary[1 % n] - boundary[0]);
  for (int i = 0; i < kEdgeSamples; ++i) {
    const double s = (i + 0.5) * step;
    while (s > edge_start + edge_length && edge + 1 < n) {
      edge_start += edge_length;
      ++edge;
      edge_length = cv::norm(boundary[(edge + 1) % n] - boundary[edge]);
    }
    if (!(edge_length > 0.0)) continue;
    const Point a = boundary[edge];
    const Point direction = (boundary[(edge + 1) % n] - a) / edge_length;
    const Point p = a + direction * std::min(edge_length, s - edge_start);
    const Point normal(-direction.y, direction.x);
    const Point left = p + normal * kSideOffset - Point(gray_origin);
    const Point right = p - normal * kSideOffset - Point(gray_origin);
    const int lx = round_to_pixel(left.x), ly = round_to_pixel(left.y);
    const int rx = round_to_pixel(right.x), ry = round_to_pixel(right.y);
    if (lx < 0 || ly < 0 || rx < 0 || ry < 0 || lx >= gray.cols || rx >= gray.cols ||
        ly >= gray.rows || ry >= gray.rows) {
      continue;
    }
    const int left_level = gray.at<uchar>(ly, lx), right_level = gray.at<uchar>(ry, rx);
    if (std::abs(left_level - right_level) >= min_step) ++supported;
    inside_sum += left_inside ? left_level : right_level;
    ++inside_count;
  }
  out.support = static_cast<double>(supported) / kEdgeSamples;
  if (inside_count > 0) out.inside_level = static_cast<double>(inside_sum) / inside_count;
  return out;
}

BoundaryEvidence measure_evidence(const Polygon& boundary, double gap_length,
                                  const Polygon& previous, const ShapeDescriptor& reference,
                                  const cv::Mat& gray, cv::Point gray_origin, double min_step,
                                  ShapeDescriptor* descriptor) {
  BoundaryEvidence e;
  const double length = perimeter(boundary);
  e.gap_share = length > 0.0 ? std::clamp(gap_length / length, 0.0, 1.0) : 1.0;
  const EdgeSamples edges = sample_edges(boundary, gray, gray_origin, min_step);
  e.edge_support = edges.support;
  e.inside_level = edges.inside_level;
  // An invalid descriptor (no area) is as unlike the reference as shapes get.
  const ShapeDescriptor shape = shape_descriptor(boundary);
  e.shape_change = std::min(1.0, shape_distance(shape, reference));
  if (descriptor != nullptr) *descriptor = shape;
  const double size = std::sqrt(area(boundary));
  e.jump = size > 0.0 && !previous.empty()
               ? std::min(1.0, cv::norm(centroid(boundary) - centroid(previous)) / size)
               : 0.0;
  return e;
}

}  // namespace scbt
