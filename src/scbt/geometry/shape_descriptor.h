// A closed boundary's shape, independent of where it is, its size and its orientation: the
// magnitudes of the Fourier coefficients of its centroid distance (Zhang & Lu 2002, "Shape-based
// image retrieval using generic Fourier descriptor"; the centroid-distance signature). Used to
// tell whether a closed cycle found while searching for a lost object is that object.
#pragma once

#include <array>

#include "scbt/geometry/polygon.h"

namespace scbt {

struct ShapeDescriptor {
  // Harmonics 1..kHarmonics of the centroid distance r(s) sampled at kSamples points equally
  // spaced along the boundary, divided by the mean of r (harmonic 0), so that:
  //  - translation: r is measured from the region's centroid;
  //  - scale: r is divided by its mean;
  //  - rotation, starting vertex, direction: each only shifts or reverses r(s), which changes the
  //    coefficients' phases, not their magnitudes.
  static constexpr int kSamples = 64;
  static constexpr int kHarmonics = 12;
  std::array<double, kHarmonics> magnitudes{};
  bool valid = false;  // false for a polygon without area or perimeter
};

// The descriptor of a closed polygon (at least 3 vertices with area; invalid otherwise).
ShapeDescriptor shape_descriptor(const Polygon& polygon);

// Euclidean distance between the magnitudes: 0 for the same shape; a circle against ellipses of
// aspect 1.1 / 1.2 / 2 gives 0.024 / 0.045 / 0.17, against a square 0.078. Infinity when either
// descriptor is invalid.
double shape_distance(const ShapeDescriptor& a, const ShapeDescriptor& b);

// The shape up to an affine map (a plane seen from another angle, locally): the polygon whitened
// by the second moments of its region (its inertia ellipse made a circle), then described as
// above. A circle and every ellipse give one descriptor; a square and every parallelogram another.
// `aspect`, when given, gets the inertia ellipse's axis ratio (>= 1; the stretch taken out), or
// infinity for an invalid polygon.
ShapeDescriptor affine_shape_descriptor(const Polygon& polygon, double* aspect = nullptr);

}  // namespace scbt
