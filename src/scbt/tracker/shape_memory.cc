#include "scbt/tracker/shape_memory.h"

#include <stdexcept>
#include <string>

namespace scbt {

ShapeMemory::ShapeMemory(double rate) : rate_(rate) {
  if (!(rate > 0.0 && rate <= 1.0)) {
    throw std::invalid_argument("ShapeMemory: rate must be in (0, 1], got " + std::to_string(rate));
  }
}

void ShapeMemory::restart(const Polygon& boundary) {
  descriptor_ = affine_shape_descriptor(boundary);
}

void ShapeMemory::remember(const Polygon& boundary) {
  const ShapeDescriptor seen = affine_shape_descriptor(boundary);
  if (!seen.valid) return;
  if (!descriptor_.valid) {
    descriptor_ = seen;
    return;
  }
  for (int k = 0; k < ShapeDescriptor::kHarmonics; ++k) {
    descriptor_.magnitudes[k] += rate_ * (seen.magnitudes[k] - descriptor_.magnitudes[k]);
  }
}

}  // namespace scbt
