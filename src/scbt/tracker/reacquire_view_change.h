// A lost object seen again from another distance or angle: its outline is then the last confident
// one scaled beyond the moderate range the search tries by itself, or foreshortened (a circle seen
// obliquely is an ellipse). The shape is compared up to an affine map (affine_shape_descriptor),
// which admits much more of the clutter, so such a match must also look like the object inside
// (reacquire_appearance.h): the colour histogram of the last kept view of it.
#pragma once

#include <optional>

#include "scbt/geometry/polygon.h"
#include "scbt/geometry/shape_descriptor.h"
#include "scbt/tracker/reacquire_appearance.h"

namespace scbt {

struct ViewChangeOptions {
  bool enabled = true;
  // Size (square root of the area) of a match against the last confident boundary's.
  double min_scale = 0.5;
  double max_scale = 2.0;
  // Change of the inertia ellipse's axis ratio, either way: a plane turned by up to about 48
  // degrees further from the camera (1 / cos 48 = 1.5).
  double max_foreshortening = 1.5;
  // histogram_similarity with the last kept view of the object (a Bhattacharyya coefficient:
  // most of the mass in the same colour bins).
  double min_appearance = 0.8;
  // Placements per frame at the scales below the moderate ones (LossOptions::min_scale), and as
  // many above them (LossOptions::max_scale), over the whole frame.
  int frame_tries = 2;

  // Throws std::invalid_argument naming the first bad value.
  void check() const;
};

class ViewChangeMatch {
 public:
  explicit ViewChangeMatch(const ViewChangeOptions& options = {});

  // The shape to find (the last confident boundary) and the object's last kept view (a frame and
  // its boundary there; an empty image: none, and no match is possible).
  void set_reference(const Polygon& outline, const cv::Mat& view, const Polygon& view_boundary);
  // The affine shape distance of `cycle` (in `frame`) to the reference when it is within
  // `max_distance`, its size, foreshortening and appearance within the options; else nullopt.
  std::optional<double> distance(const cv::Mat& frame, const Polygon& cycle,
                                 double max_distance) const;

 private:
  ViewChangeOptions options_;
  ShapeDescriptor reference_;
  double reference_aspect_ = 1.0;
  double reference_size_ = 0.0;
  Polygon view_boundary_;  // the view the histogram is of (recomputed when it changes)
  RegionHistogram appearance_;
};

}  // namespace scbt
