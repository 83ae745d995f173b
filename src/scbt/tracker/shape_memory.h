// The tracked outline's shape remembered over many frames: what the boundary choice weighs a
// candidate's change of shape against (TrackerOptions::shape_weight).
#pragma once

#include "scbt/geometry/polygon.h"
#include "scbt/geometry/shape_descriptor.h"

namespace scbt {

// An exponential average of the affine shape descriptors (affine_shape_descriptor) of the
// boundaries it is shown. Affine: a rim or a face seen from another angle keeps its descriptor,
// so that the memory need follow only what the view does to an outline that is not planar.
// Slow: a boundary creeping into the background a little each frame, each step too small to
// notice against the frame before, drifts away from it.
class ShapeMemory {
 public:
  // `rate`: the weight of each new boundary, in (0, 1]; 1 remembers only the last one.
  explicit ShapeMemory(double rate = 0.05);

  // Forgets what was remembered: the shape is `boundary`'s.
  void restart(const Polygon& boundary);
  // Moves the remembered shape towards `boundary`'s by the rate (restarts when nothing is
  // remembered). A polygon without area or perimeter leaves it as it is.
  void remember(const Polygon& boundary);
  // The remembered shape; invalid until a valid boundary was shown.
  const ShapeDescriptor& descriptor() const { return descriptor_; }

 private:
  double rate_;
  ShapeDescriptor descriptor_;
};

}  // namespace scbt
