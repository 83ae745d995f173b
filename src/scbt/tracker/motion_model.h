// A constant-velocity prediction of where the boundary will be in the next frame, from how it
// moved between the last two tracked frames: its centroid's translation and its area's growth
// rate (a similarity motion without rotation). The search band then follows steady motion that
// moves the boundary a large part of the band per frame (low frame rates, fast camera moves),
// and the area-similarity gate (Eq. 2) compares candidates with the predicted area, so that an
// approaching or receding object that grows or shrinks by more than the gate between frames
// is not rejected.
#pragma once

#include "scbt/geometry/polygon.h"

namespace scbt {

class MotionModel {
 public:
  // Forgets the history: the boundary starts at rest.
  void reset();
  // Records the boundary tracked in the current frame, or a held frame (no measurement).
  void update(const Polygon& tracked);
  void update_held();
  // `last` (the last tracked boundary) moved as predicted for the next frame, and, with
  // `with_scale`, also scaled about its centroid by the predicted growth.
  void predict(const Polygon& last, bool with_scale, Polygon* predicted) const;
  // The predicted area of the next frame's boundary over the last tracked one's.
  double predicted_area_ratio() const;
  // The same for a steady shrinking only: from the slowest of the last kSustainedSteps growth
  // rates when all of them are negative, else 1.
  double sustained_shrink_ratio() const;

 private:
  bool has_last_ = false;
  Point last_centroid_;
  double last_log_area_ = 0.0;
  Point velocity_;              // centroid motion per frame
  double log_area_rate_ = 0.0;  // d(log area) per frame
  int frames_since_last_ = 1;   // frames from the last tracked one to the next to be tracked
  static constexpr int kSustainedSteps = 3;
  double recent_rates_[kSustainedSteps] = {};  // the last log_area_rate_ values, oldest replaced
  int num_rates_ = 0;
};

// The centroid of a closed polygon's area (the vertex mean when the area vanishes).
Point area_centroid(const Polygon& polygon);

}  // namespace scbt
