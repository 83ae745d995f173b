#include "scbt/tracker/tracker_options.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace scbt {

void TrackerOptions::check() const {
  detector.check();
  adaptive_thresholds.check();
  exposure.check();
  loss.check();
  appearance.check();
  blur.check();
  if (!(filter_distance > 0.0 && filter_distance <= 1000.0)) {
    throw std::invalid_argument("filter_distance must be in (0, 1000] pixels, got " +
                                std::to_string(filter_distance));
  }
  if (!(min_area_similarity >= 0.0 && min_area_similarity < 1.0)) {
    throw std::invalid_argument("min_area_similarity must be in [0, 1), got " +
                                std::to_string(min_area_similarity));
  }
  if (!(similarity_exponent >= 0.0 && similarity_exponent <= 10.0)) {
    throw std::invalid_argument("similarity_exponent must be in [0, 10], got " +
                                std::to_string(similarity_exponent));
  }
  if (!(shape_weight >= 0.0 && shape_weight <= 100.0)) {
    throw std::invalid_argument("shape_weight must be in [0, 100], got " +
                                std::to_string(shape_weight));
  }
  if (!(cost_tolerance >= 0.0 && cost_tolerance <= 10.0)) {
    throw std::invalid_argument("cost_tolerance must be in [0, 10], got " +
                                std::to_string(cost_tolerance));
  }
  if (!(min_motion_agreement >= -1.0 && min_motion_agreement <= 1.0)) {
    throw std::invalid_argument("min_motion_agreement must be in [-1, 1], got " +
                                std::to_string(min_motion_agreement));
  }
  if (!(min_predicted_move >= 0.0 && min_predicted_move <= 100.0)) {
    throw std::invalid_argument("min_predicted_move must be in [0, 100] (x filter_distance), got " +
                                std::to_string(min_predicted_move));
  }
  if (max_segments < 3 || max_segments > 100000) {
    throw std::invalid_argument("max_segments must be in 3..100000, got " +
                                std::to_string(max_segments));
  }
  if (bdsp.seed_stride < 1 || bdsp.seed_stride > 1000) {
    throw std::invalid_argument("seed_stride must be in 1..1000, got " +
                                std::to_string(bdsp.seed_stride));
  }
}

}  // namespace scbt
