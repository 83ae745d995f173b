// A common face for every tracker that turns frames into a boundary polygon: scbt's own BDSP
// tracker and the peers users would otherwise pick (for side-by-side evaluation).
#pragma once

#include <memory>
#include <opencv2/core/mat.hpp>
#include <string>
#include <utility>
#include <vector>

#include "scbt/tracker/tracker.h"

namespace scbt {

class PolygonTracker {
 public:
  virtual ~PolygonTracker() = default;
  // Same contract as Tracker::init: throws std::invalid_argument on a bad frame or polygon.
  virtual void init(const cv::Mat& frame, const Polygon& polygon) = 0;
  // result.boundary is always a polygon; result.held marks a frame where the tracker kept its
  // previous answer. Peers fill the timing fields they can (grouping_ms = their whole time).
  virtual TrackResult track(const cv::Mat& frame) = 0;
};

// scbt's own tracker behind the common face; tracker() reaches its debug data and options.
class BdspPolygonTracker : public PolygonTracker {
 public:
  explicit BdspPolygonTracker(Tracker tracker) : tracker_(std::move(tracker)) {}
  void init(const cv::Mat& frame, const Polygon& polygon) override {
    tracker_.init(frame, polygon);
  }
  TrackResult track(const cv::Mat& frame) override { return tracker_.track(frame); }
  Tracker& tracker() { return tracker_; }

 private:
  Tracker tracker_;
};

// Names accepted by make_polygon_tracker, in a stable order.
std::vector<std::string> polygon_tracker_names();
// The name among polygon_tracker_names() that `name` stands for: "scbt" for its alias "bdsp",
// `name` itself otherwise.
std::string canonical_polygon_tracker_name(const std::string& name);

// "scbt" (alias "bdsp"; configured by `options`), the peers "ecc", "klt", "csrt" (ecc_tracker.h,
// klt_tracker.h, csrt_tracker.h, default settings) and "rrc" (rrc_tracker.h, using the detector
// and filter distance of `options`), and "static" (the initial polygon held).
// Throws std::invalid_argument for an unknown name.
std::unique_ptr<PolygonTracker> make_polygon_tracker(const std::string& name,
                                                     const TrackerOptions& options = {});

}  // namespace scbt
