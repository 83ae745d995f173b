#include "scbt/peers/rrc_tracker.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "scbt/choice/boundary_choice.h"
#include "scbt/filter/segment_filter.h"
#include "scbt/graph/segment_graph.h"
#include "scbt/peers/peer_common.h"

namespace scbt {

void RrcTrackerOptions::check() const {
  detector.check();
  if (!(filter_distance > 0.0)) {
    throw std::invalid_argument("rrc filter_distance must be > 0, got " +
                                std::to_string(filter_distance));
  }
  if (max_segments < 2) {
    throw std::invalid_argument("rrc max_segments must be >= 2, got " +
                                std::to_string(max_segments));
  }
  ratio.check();
}

RrcTracker::RrcTracker(const RrcTrackerOptions& options) : options_(options) {
  options_.check();
  detector_ = make_line_detector(options_.detector);
}

RrcTracker::~RrcTracker() = default;

void RrcTracker::init(const cv::Mat& frame, const Polygon& polygon) {
  cv::Mat gray;
  check_tracker_init(frame, polygon, &gray);
  frame_size_ = frame.size();
  boundary_ = polygon;
}

TrackResult RrcTracker::track(const cv::Mat& frame) {
  if (boundary_.empty()) throw std::logic_error("RrcTracker::track called before init");
  TrackResult result;
  const Stopwatch line_watch;
  cv::Mat gray;
  to_gray(frame, &gray);
  check_frame_size(frame, frame_size_);
  const std::vector<Segment> detected = detector_->detect(gray);
  result.line_ms = line_watch.elapsed_ms();

  const Stopwatch grouping_watch;
  std::vector<Segment> kept =
      filter_segments_near_boundary(detected, boundary_, options_.filter_distance);
  if (static_cast<int>(kept.size()) > options_.max_segments) {
    std::stable_sort(kept.begin(), kept.end(),
                     [](const Segment& l, const Segment& r) { return l.length() > r.length(); });
    kept.resize(options_.max_segments);
  }
  const SegmentGraph graph = build_segment_graph(kept);
  const std::optional<RatioContour> contour =
      find_ratio_contour(graph, centroid(boundary_), options_.ratio);
  if (contour) {
    result.cost = contour->ratio;
    result.area_similarity = area_similarity(area(boundary_), contour->area);
    result.num_candidates = contour->iterations;
    boundary_ = contour->polygon;
  } else {
    result.held = true;
  }
  result.grouping_ms = grouping_watch.elapsed_ms();
  result.boundary = boundary_;
  result.num_detected = static_cast<int>(detected.size());
  result.num_kept = static_cast<int>(kept.size());
  result.num_vertices = graph.num_vertices();
  result.num_edges = graph.num_edges();
  return result;
}

}  // namespace scbt
