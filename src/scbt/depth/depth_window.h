// One boundary sample's depth: the nearest surface in a small window on the object's side.
//
// A depth pixel on an object's edge is unreliable: holes read 0, mixed pixels average the object
// and the background, and noise grows with z^2. A few pixels inwards lies the object itself, and
// it is the nearest surface there (it occludes what is behind it; a bowl's inside, seen past its
// rim, is farther). So the window's valid depths are grouped into surfaces (depths within the
// noise tolerance of each other) and the median of the nearest surface with enough pixels is
// taken: an isolated too-near outlier, mixed pixels and the farther inside are all passed over.
// The surface's pixels lie a few pixels inside the boundary; their mean position is returned
// too, so the 3-D point is lifted where its depth was measured (on a tilted rim, lifting it on
// the boundary's own ray would flatten the fitted plane).
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
  Point pixel;     // mean image position of the surface's pixels
};

struct DepthPixel {
  double z;
  float x, y;
  bool operator<(const DepthPixel& other) const { return z < other.z; }
};

// `depth` is CV_16UC1 (times options.depth_scale) or CV_32FC1 (metres); `scratch` is reused
// between calls.
SurfaceDepth nearest_surface_depth(const cv::Mat& depth, const BoundarySample& sample,
                                   const DepthOptions& options, std::vector<DepthPixel>* scratch);

}  // namespace scbt
