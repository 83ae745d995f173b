#include "scbt/render/annotate.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>

namespace scbt {

cv::Scalar state_color(TrackState state) {
  switch (state) {
    case TrackState::kTracking:
      return cv::Scalar(0, 220, 0);  // green
    case TrackState::kUncertain:
      return cv::Scalar(0, 170, 255);  // amber
    case TrackState::kLost:
      return cv::Scalar(0, 0, 255);  // red
  }
  return cv::Scalar(255, 255, 255);
}

namespace {

std::vector<cv::Point> to_cv_points(const Polygon& polygon) {
  std::vector<cv::Point> points;
  points.reserve(polygon.size());
  for (const Point& p : polygon) points.emplace_back(cvRound(p.x), cvRound(p.y));
  return points;
}

}  // namespace

void draw_polygon(cv::Mat* image, const Polygon& polygon, const cv::Scalar& color, int thickness) {
  const std::vector<cv::Point> points = to_cv_points(polygon);
  if (points.size() >= 2) {
    cv::polylines(*image, points, true, color, thickness, cv::LINE_AA);
  }
}

cv::Mat annotate_frame(const cv::Mat& frame, const TrackDebug& debug, const TrackResult& result,
                       const std::string& status) {
  cv::Mat canvas;
  if (frame.channels() == 1) {
    cv::cvtColor(frame, canvas, cv::COLOR_GRAY2BGR);
  } else if (frame.channels() == 4) {
    cv::cvtColor(frame, canvas, cv::COLOR_BGRA2BGR);
  } else {
    canvas = frame.clone();
  }
  for (const Segment& s : debug.detected) {
    cv::line(canvas, s.a, s.b, cv::Scalar(150, 150, 150), 1, cv::LINE_AA);
  }
  const SegmentGraph& graph = debug.graph;
  for (const GraphEdge& e : graph.edges) {
    if (e.detected) continue;
    cv::line(canvas, graph.vertices[e.u], graph.vertices[e.v], cv::Scalar(255, 120, 0), 1,
             cv::LINE_AA);
  }
  for (const GraphEdge& e : graph.edges) {
    if (!e.detected) continue;
    cv::line(canvas, graph.vertices[e.u], graph.vertices[e.v], cv::Scalar(0, 0, 255), 2,
             cv::LINE_AA);
  }
  const cv::Scalar color = state_color(result.state);
  draw_polygon(&canvas, result.boundary, color, 2);
  if (result.state != TrackState::kTracking && !result.boundary.empty()) {
    // Named beside the boundary too: the colour alone does not reach every reader.
    const cv::Rect box = cv::boundingRect(to_cv_points(result.boundary));
    const std::string label = result.state == TrackState::kLost ? "LOST" : "uncertain";
    const cv::Point at(std::max(box.x, 2), std::max(box.y - 6, 14));
    cv::putText(canvas, label, at, cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(0, 0, 0), 3,
                cv::LINE_AA);
    cv::putText(canvas, label, at, cv::FONT_HERSHEY_SIMPLEX, 0.5, color, 1, cv::LINE_AA);
  }
  if (!status.empty()) {
    cv::putText(canvas, status, {8, 20}, cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(0, 0, 0), 3,
                cv::LINE_AA);
    cv::putText(canvas, status, {8, 20}, cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(255, 255, 255),
                1, cv::LINE_AA);
  }
  return canvas;
}

}  // namespace scbt
