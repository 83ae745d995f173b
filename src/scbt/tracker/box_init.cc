#include "scbt/tracker/box_init.h"

#include <stdexcept>
#include <string>

#include "scbt/choice/boundary_choice.h"
#include "scbt/graph/segment_graph.h"
#include "scbt/tracker/tracker_impl.h"

namespace scbt {

std::optional<Polygon> most_salient_boundary(const std::vector<Segment>& segments, double min_area,
                                             const BdspOptions& options) {
  const SegmentGraph graph = build_segment_graph(segments);
  CycleSearch search;
  search.run(graph, options);
  int best = -1;
  double best_cost = 0.0;
  double best_area = 0.0;
  for (int k = 0; k < search.size(); ++k) {
    const CandidateSummary& c = search.candidates()[k];
    if (!(c.area >= min_area)) continue;
    const double cost = grouping_cost(c.gap_length, c.area);
    if (best < 0 || cost < best_cost || (cost == best_cost && c.area > best_area)) {
      best = k;
      best_cost = cost;
      best_area = c.area;
    }
  }
  if (best < 0) return std::nullopt;
  std::vector<int> cycle;
  search.vertices(best, &cycle);
  Polygon polygon;
  for (int v : cycle) polygon.push_back(graph.vertices[v]);
  return polygon;
}

Polygon Tracker::Impl::init_from_box(const cv::Mat& frame, const cv::Rect& box) {
  scale_thresholds_to_exposure(frame);
  cv::Mat gray;
  to_exposed_gray(frame, &gray);  // throws for a bad frame
  const cv::Rect frame_rect(cv::Point(0, 0), frame.size());
  if (box.width < 8 || box.height < 8 || (box & frame_rect) != box) {
    throw std::invalid_argument("the box " + std::to_string(box.x) + "," + std::to_string(box.y) +
                                "," + std::to_string(box.width) + "," + std::to_string(box.height) +
                                " must be at least 8x8 pixels and inside the " +
                                std::to_string(frame.cols) + "x" + std::to_string(frame.rows) +
                                " frame");
  }
  const std::vector<Segment> segments = detector_->detect_in(gray(box), box.tl(), frame.size());
  const std::optional<Polygon> boundary =
      most_salient_boundary(segments, kMinBoxAreaShare * box.area(), options_.bdsp);
  if (!boundary) {
    throw std::runtime_error("no closed boundary found inside the box (" +
                             std::to_string(segments.size()) + " segments detected)");
  }
  init(frame, *boundary);
  return *boundary;
}

}  // namespace scbt
