// Peer "ecc": registration-based homography tracking with OpenCV's findTransformECC
// (Evangelidis & Psarakis 2008), the family of the paper's ESM baseline. The template is the
// first frame's grey region inside the polygon's bounding box (plus template_margin); every frame
// the homography from template to frame is refined coarse to fine, warm-started from the previous
// frame's, on a crop around the previous boundary. By default no input mask is used: on the
// dataset (first 300 frames of Bowl and BookStand) masking ECC to the previous boundary, shrunk
// or grown, tracked worse than the plain bounding box.
#pragma once

#include <opencv2/core/mat.hpp>
#include <vector>

#include "scbt/peers/polygon_tracker.h"

namespace scbt {

struct EccTrackerOptions {
  // Pixels added around the polygon's bounding box to form the template.
  int template_margin = 0;
  // The finest level works on the template downscaled so its longer side is at most this.
  int max_template_side = 160;
  // Coarser levels (factor 2 each) are added while the longer side stays at least this.
  int min_template_side = 40;
  int max_levels = 4;
  // Per-level ECC termination: iteration count and correlation increment.
  int max_iterations = 30;
  double epsilon = 1e-4;
  // ECC only uses input pixels inside the previous boundary grown by this many pixels (so the
  // boundary's own contrast counts, the background farther out does not); negative: no mask,
  // the whole template box counts.
  int mask_growth = -1;
  // Gaussian smoothing kernel findTransformECC applies (odd).
  int gauss_filter_size = 5;
  // A warp whose polygon's area leaves [area0 / f, area0 * f] is rejected (the frame is held).
  double max_area_factor = 4.0;

  void check() const;
};

class EccTracker : public PolygonTracker {
 public:
  explicit EccTracker(const EccTrackerOptions& options = {});
  void init(const cv::Mat& frame, const Polygon& polygon) override;
  TrackResult track(const cv::Mat& frame) override;

 private:
  EccTrackerOptions options_;
  cv::Size frame_size_;
  Polygon polygon0_;  // the initial polygon, in template coordinates
  double area0_ = 0.0;
  std::vector<cv::Mat> templates_;  // CV_32F, finest first
  std::vector<double> scales_;      // template scale of each level
  cv::Mat warp_;                    // 3x3 CV_64F: template coordinates -> frame coordinates
  Polygon boundary_;
};

}  // namespace scbt
