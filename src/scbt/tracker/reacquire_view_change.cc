#include "scbt/tracker/reacquire_view_change.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace scbt {

void ViewChangeOptions::check() const {
  if (!(min_scale > 0.05 && min_scale <= 1.0 && max_scale >= 1.0 && max_scale < 20.0)) {
    throw std::invalid_argument(
        "view_change scales must satisfy 0.05 < min_scale <= 1 <= max_scale < 20");
  }
  if (!(max_foreshortening >= 1.0 && max_foreshortening < 100.0)) {
    throw std::invalid_argument("view_change.max_foreshortening must be in [1, 100)");
  }
  if (!(min_appearance >= 0.0 && min_appearance <= 1.0)) {
    throw std::invalid_argument("view_change.min_appearance must be in [0, 1]");
  }
  if (frame_tries < 0 || frame_tries > 100) {
    throw std::invalid_argument("view_change.frame_tries must be in 0..100");
  }
}

ViewChangeMatch::ViewChangeMatch(const ViewChangeOptions& options) : options_(options) {
  options_.check();
}

void ViewChangeMatch::set_reference(const Polygon& outline, const cv::Mat& view,
                                    const Polygon& view_boundary) {
  reference_ = affine_shape_descriptor(outline, &reference_aspect_);
  reference_size_ = std::sqrt(area(outline));
  if (view.empty()) {
    view_boundary_.clear();
    appearance_.bins.clear();
  } else if (view_boundary != view_boundary_) {
    view_boundary_ = view_boundary;
    appearance_ = region_histogram(view, view_boundary);
  }
}

std::optional<double> ViewChangeMatch::distance(const cv::Mat& frame, const Polygon& cycle,
                                                double max_distance) const {
  if (!options_.enabled || appearance_.bins.empty() || !reference_.valid) return std::nullopt;
  const double scale = std::sqrt(area(cycle)) / reference_size_;
  if (!(scale >= options_.min_scale && scale <= options_.max_scale)) return std::nullopt;
  double aspect = 0.0;
  const double d = shape_distance(affine_shape_descriptor(cycle, &aspect), reference_);
  if (!(d <= max_distance)) return std::nullopt;
  const double stretch = std::max(aspect / reference_aspect_, reference_aspect_ / aspect);
  if (!(stretch <= options_.max_foreshortening)) return std::nullopt;
  if (histogram_similarity(region_histogram(frame, cycle), appearance_) < options_.min_appearance) {
    return std::nullopt;
  }
  return d;
}

}  // namespace scbt
