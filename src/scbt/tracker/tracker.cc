#include "scbt/tracker/tracker.h"

#include <algorithm>
#include <chrono>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

#include "scbt/geometry/polygon_io.h"
#include "scbt/grouping/bdsp.h"
#include "scbt/grouping/boundary_choice.h"
#include "scbt/grouping/segment_filter.h"
#include "scbt/lines/line_detector.h"

namespace scbt {
namespace {

using Clock = std::chrono::steady_clock;

double elapsed_ms(Clock::time_point since) {
  return std::chrono::duration<double, std::milli>(Clock::now() - since).count();
}

}  // namespace

void to_gray(const cv::Mat& frame, cv::Mat* gray) {
  if (frame.empty()) throw std::invalid_argument("frame is empty");
  if (frame.depth() != CV_8U) {
    throw std::invalid_argument("frame must be 8-bit, got depth " + std::to_string(frame.depth()));
  }
  switch (frame.channels()) {
    case 1:
      *gray = frame;
      return;
    case 3:
      cv::cvtColor(frame, *gray, cv::COLOR_BGR2GRAY);
      return;
    case 4:
      cv::cvtColor(frame, *gray, cv::COLOR_BGRA2GRAY);
      return;
    default:
      throw std::invalid_argument("frame must have 1, 3 or 4 channels, got " +
                                  std::to_string(frame.channels()));
  }
}

Tracker::Tracker(const TrackerOptions& options) : options_(options) {
  options_.check();
  detector_ = make_line_detector(options_.detector);
}

Tracker::~Tracker() = default;
Tracker::Tracker(Tracker&&) noexcept = default;
Tracker& Tracker::operator=(Tracker&&) noexcept = default;

void Tracker::init(const cv::Mat& frame, const Polygon& polygon) {
  to_gray(frame, &gray_);
  check_boundary_polygon(polygon);
  const cv::Rect2d frame_rect(0, 0, frame.cols, frame.rows);
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Point& p = polygon[i];
    if (p.x < 0 || p.y < 0 || p.x > frame.cols || p.y > frame.rows) {
      throw std::invalid_argument("polygon vertex " + std::to_string(i + 1) + " (" +
                                  std::to_string(p.x) + ", " + std::to_string(p.y) +
                                  ") is outside the " + std::to_string(frame.cols) + "x" +
                                  std::to_string(frame.rows) + " frame");
    }
  }
  boundary_ = polygon;
  boundary_area_ = area(polygon);
  frame_size_ = frame.size();
}

TrackResult Tracker::track(const cv::Mat& frame) {
  if (!initialized()) throw std::logic_error("Tracker::track called before init");
  TrackResult result;

  const Clock::time_point line_start = Clock::now();
  if (frame.empty()) to_gray(frame, &gray_);  // throws
  if (frame.size() != frame_size_) {
    throw std::invalid_argument("frame size changed from " + std::to_string(frame_size_.width) +
                                "x" + std::to_string(frame_size_.height) + " to " +
                                std::to_string(frame.cols) + "x" + std::to_string(frame.rows));
  }
  // Only segments near the previous boundary can survive the distance filter, so only the
  // window around it is converted and searched (crop_to_boundary; whole frame otherwise).
  cv::Rect roi(cv::Point(0, 0), frame_size_);
  if (options_.detector.crop_to_boundary) {
    roi = detection_roi(boundary_, options_.filter_distance + options_.detector.roi_padding,
                        frame_size_);
    if (roi.empty()) roi = cv::Rect(cv::Point(0, 0), frame_size_);
  }
  to_gray(frame(roi), &gray_);
  std::vector<Segment> detected = detector_->detect_in(gray_, roi.tl(), frame_size_);
  result.line_ms = elapsed_ms(line_start);

  const Clock::time_point grouping_start = Clock::now();
  std::vector<Segment> kept =
      filter_segments_near_boundary(detected, boundary_, options_.filter_distance);
  if (static_cast<int>(kept.size()) > options_.max_segments) {
    result.num_dropped = static_cast<int>(kept.size()) - options_.max_segments;
    std::nth_element(
        kept.begin(), kept.begin() + options_.max_segments, kept.end(),
        [](const Segment& a, const Segment& b) { return a.length() > b.length(); });
    kept.resize(options_.max_segments);
  }
  SegmentGraph graph = build_segment_graph(kept);
  const std::vector<CycleCandidate> candidates = search_cycle_candidates(graph, options_.bdsp);
  const std::optional<BoundaryChoice> choice = choose_boundary_stable(
      candidates, graph, boundary_, options_.min_area_similarity, options_.cost_tolerance);
  if (choice) {
    boundary_ = candidate_polygon(graph, candidates[choice->index]);
    boundary_area_ = candidates[choice->index].area;
    result.cost = choice->cost;
    result.area_similarity = choice->similarity;
  } else {
    result.held = true;
  }
  result.grouping_ms = elapsed_ms(grouping_start);

  result.boundary = boundary_;
  result.num_detected = static_cast<int>(detected.size());
  result.num_kept = static_cast<int>(kept.size());
  result.num_vertices = graph.num_vertices();
  result.num_edges = graph.num_edges();
  result.num_candidates = static_cast<int>(candidates.size());
  if (keep_debug_) {
    debug_.detected = std::move(detected);
    debug_.graph = std::move(graph);
  }
  return result;
}

}  // namespace scbt
