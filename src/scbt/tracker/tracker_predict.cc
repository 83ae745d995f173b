// Where a frame's search looks when the boundary moves (TrackerOptions::measure_motion): the image
// motion around it, measured by phase correlation against the last tracked frame's window.
#include <opencv2/core.hpp>

#include "scbt/lines/line_detector.h"
#include "scbt/motion/motion_estimate.h"
#include "scbt/tracker/tracker_impl.h"

namespace scbt {

void Tracker::Impl::place_by_image_motion(const cv::Mat& frame) {
  predicted_ = boundary_;
  // The boundary's last velocity only decides whether to measure: a fast camera's steps recur
  // from frame to frame, while a noisy frame's jump (another cycle chosen) says nothing of where
  // the object goes and is not followed.
  motion_.predict(boundary_, /*with_scale=*/false, &extrapolated_);
  const Point step = area_centroid(extrapolated_) - area_centroid(boundary_);
  const double min_move = options_.min_predicted_move * options_.filter_distance;
  if (cv::norm(step) < min_move) return;
  if (reference_gray_.empty()) return;
  to_exposed_gray(frame(reference_roi_), &cut_gray_);
  // Measured on the windows averaged down to at most 64 px a side: a few px of precision, well
  // inside the band searched around the moved boundary, at about a tenth of the cost of 200 px.
  constexpr int kSide = 64;
  const std::optional<TranslationEstimate> image_motion =
      translation_.estimate(reference_gray_, cut_gray_, kSide);
  // A move the band absorbs is not followed: on a compressed or low-resolution frame the
  // measured shift of a still scene is noise that walks the band off the boundary.
  if (!image_motion || cv::norm(image_motion->shift) < min_move) return;
  for (Point& p : predicted_) p += image_motion->shift;
}

}  // namespace scbt
