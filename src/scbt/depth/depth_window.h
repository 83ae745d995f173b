// One boundary sample's depth: the nearest surface in a small window on the object's side.
//
// A depth pixel on an object's edge is unreliable: holes read 0, mixed pixels average the object
// and the background, and noise grows with z^2. A few pixels inwards lies the object itself, and
// it is the nearest surface there (it occludes what is behind it; a bowl's inside, seen past its
// rim, is farther). So the window's valid depths are grouped into surfaces (depths within the
// noise tolerance of each other) and the median of the nearest surface with enough pixels is
// taken: an isolated too-near outlier, mixed pixels and the farther inside are all passed over.
// Of the surface's pixels only those of the window row nearest the boundary are averaged (a
// bowl's inner wall just past its lip can be within the tolerance of the lip's depth, but is
// not on the rim), and their mean position is returned with the depth, so the 3-D point is
// lifted where its depth was measured (on a tilted rim, lifting it on the boundary's own ray
// would flatten the fitted plane).
#pragma once

#include <opencv2/core/mat.hpp>
#include <vector>

#include "scbt/depth/boundary_samples.h"
#include "scbt/depth/depth_options.h"

namespace scbt {

// Depths within this of each other belong to one surface: max(tolerance_floor,
// outlier_sigmas * noise_at_1m * z^2).
double surface_tolerance(const DepthOptions& options, double z);

struct SurfaceDepth {
  double z = 0.0;  // metres; 0 when the window has no surface of min_surface_pixels pixels
  Point pixel;     // mean image position of the surface's pixels that were averaged
};

struct DepthPixel {
  double z;
  float x, y;
  int row;  // how far inside the boundary: 0 = the window's first row
  bool operator<(const DepthPixel& other) const { return z < other.z; }
};

// `depth` is CV_16UC1 (times options.depth_scale) or CV_32FC1 (metres); `scratch` is reused
// between calls.
SurfaceDepth nearest_surface_depth(const cv::Mat& depth, const BoundarySample& sample,
                                   const DepthOptions& options, std::vector<DepthPixel>* scratch);

}  // namespace scbt
