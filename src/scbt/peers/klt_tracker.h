// Peer "klt": pyramidal Lucas-Kanade feature tracking inside the boundary with a RANSAC
// homography (the family of the paper's RKLT baseline). Features are detected inside the initial
// polygon; each keeps its position in the first frame, so the homography is always estimated from
// frame 1 to the current frame (no drift from chaining). When too few features survive, new ones
// are detected inside the current polygon and mapped back to frame 1 through the current warp.
#pragma once

#include <opencv2/core/mat.hpp>
#include <vector>

#include "scbt/peers/polygon_tracker.h"

namespace scbt {

struct KltTrackerOptions {
  int max_features = 300;
  double quality_level = 0.01;  // goodFeaturesToTrack, relative to the strongest corner
  double min_distance = 5.0;    // pixels between features
  int window_size = 21;         // Lucas-Kanade window (pixels, odd)
  int pyramid_levels = 3;
  // Forward-backward check: a feature tracked back to the previous frame must land within this
  // (pixels) of where it started; <= 0 disables the check.
  double max_forward_backward_error = 1.0;
  double ransac_threshold = 3.0;  // findHomography reprojection threshold (pixels)
  // Re-detect when fewer than this fraction of max_features (and at least 8) survive.
  double redetect_fraction = 0.5;
  // A homography whose polygon's area leaves [area0 / f, area0 * f] is rejected (held).
  double max_area_factor = 4.0;

  void check() const;
};

class KltTracker : public PolygonTracker {
 public:
  explicit KltTracker(const KltTrackerOptions& options = {});
  void init(const cv::Mat& frame, const Polygon& polygon) override;
  TrackResult track(const cv::Mat& frame) override;

  int num_features() const { return static_cast<int>(current_.size()); }

 private:
  // Adds features detected in `gray` inside `boundary_`, their frame-1 positions through warp_.
  void detect_features(const cv::Mat& gray);

  KltTrackerOptions options_;
  cv::Size frame_size_;
  Polygon polygon0_;
  double area0_ = 0.0;
  cv::Mat previous_gray_;
  std::vector<cv::Point2f> reference_;  // feature positions in frame 1
  std::vector<cv::Point2f> current_;    // the same features in the previous frame
  cv::Mat warp_;                        // 3x3 CV_64F homography frame 1 -> current frame
  Polygon boundary_;
};

}  // namespace scbt
