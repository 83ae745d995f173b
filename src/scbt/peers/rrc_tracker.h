// Peer "rrc": the paper's grouping baseline. Each frame runs scbt's own stages up to the graph
// (line detection, the distance filter around the previous boundary, Delaunay gap filling), then
// picks the ratio contour (ratio_contour.h: least gap length / area alternate cycle) instead of
// BDSP + the area-similarity choice. There is no area-similarity constraint (that is scbt's
// addition): the frame is held only when no cycle is found.
#pragma once

#include <memory>
#include <opencv2/core/mat.hpp>

#include "scbt/lines/line_detector.h"
#include "scbt/peers/polygon_tracker.h"
#include "scbt/peers/ratio_contour.h"

namespace scbt {

struct RrcTrackerOptions {
  LineDetectorOptions detector;   // same detector as scbt's tracker by default
  double filter_distance = 20.0;  // pixels, as scbt's distance filter
  // The assignment problem is cubic in the number of segments: beyond this many kept segments,
  // only the longest are used (keeps a frame well under 100 ms).
  int max_segments = 100;
  RatioContourOptions ratio;

  void check() const;
};

class RrcTracker : public PolygonTracker {
 public:
  explicit RrcTracker(const RrcTrackerOptions& options = {});
  ~RrcTracker() override;
  void init(const cv::Mat& frame, const Polygon& polygon) override;
  TrackResult track(const cv::Mat& frame) override;

 private:
  RrcTrackerOptions options_;
  std::unique_ptr<LineDetector> detector_;
  cv::Size frame_size_;
  Polygon boundary_;
};

}  // namespace scbt
