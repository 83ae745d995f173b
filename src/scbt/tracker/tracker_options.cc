#include "scbt/tracker/tracker_options.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "scbt/tracker/option_table.h"

namespace scbt {

void TrackerOptions::check() const {
  // The user options first, so that every interface reports them in the table's words.
  check_user_options(*this);
  detector.check();
  adaptive_thresholds.check();
  exposure.check();
  loss.check();
  appearance.check();
  blur.check();
  if (!(similarity_exponent >= 0.0 && similarity_exponent <= 10.0)) {
    throw std::invalid_argument("similarity_exponent must be in [0, 10], got " +
                                std::to_string(similarity_exponent));
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
  // Switches that act only through another: set on their own they would do nothing.
  if (!predict_motion) {
    const std::pair<bool, const char*> needs_prediction[] = {
        {measure_motion, "measure_motion"},
        {confirm_motion, "confirm_motion"},
        {fall_back_unmoved, "fall_back_unmoved"},
        {gate_sustained_shrink, "gate_sustained_shrink"}};
    for (const auto& [on, name] : needs_prediction) {
      if (on) {
        throw std::invalid_argument(std::string(name) +
                                    " acts only with predict_motion: turn it off too");
      }
    }
  }
  if (adaptive_thresholds.enabled) {
    if (smooth_noisy_frames) {
      throw std::invalid_argument(
          "smooth_noisy_frames acts only with adaptive thresholds off (the adapted ones smooth "
          "every frame): turn it off too");
    }
    if (adaptive_thresholds.retry_weak_frames) {
      throw std::invalid_argument(
          "retry_weak_frames acts only with adaptive thresholds off (every frame is adapted): "
          "turn it off too");
    }
  }
}

}  // namespace scbt
