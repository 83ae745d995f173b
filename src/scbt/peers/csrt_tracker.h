// Peer "csrt": OpenCV contrib's CSRT correlation-filter box tracker (Lukežič et al. 2017). It is
// initialised with the polygon's bounding box; each frame the polygon is moved with the box's
// centre and scaled with its size (CSRT keeps the box's aspect ratio, so the scale is uniform).
#pragma once

#include <opencv2/core/mat.hpp>
#include <opencv2/core/types.hpp>
#include <opencv2/video/tracking.hpp>

#include "scbt/peers/polygon_tracker.h"

namespace scbt {

struct CsrtTrackerOptions {
  // A box whose area leaves [area0 / f, area0 * f] of the initial box's is rejected (the frame is
  // held): the same area guard as the other peers.
  double max_area_factor = 4.0;

  void check() const;
};

class CsrtTracker : public PolygonTracker {
 public:
  explicit CsrtTracker(const CsrtTrackerOptions& options = {});
  ~CsrtTracker() override;
  void init(const cv::Mat& frame, const Polygon& polygon) override;
  TrackResult track(const cv::Mat& frame) override;

 private:
  CsrtTrackerOptions options_;
  cv::Ptr<cv::Tracker> tracker_;  // a cv::TrackerCSRT
  cv::Size frame_size_;
  Polygon polygon0_;
  cv::Rect2d box0_;
  double area0_ = 0.0;
  Polygon boundary_;
};

}  // namespace scbt
