// One boundary sample's depth: the nearest surface in a small window on the object's side.
//
// A depth pixel on an object's edge is unreliable: holes read 0, mixed pixels average the object
// and the background, and noise grows with z^2. A few pixels inwards lies the object itself, and
// it is the nearest surface there (it occludes what is behind it; a bowl's inside, seen past its
// rim, is farther). So the window's valid depths are grouped into surfaces (depths within the
// noise tolerance of each other) and the median of the nearest surface with enough pixels is
// taken: an isolated too-near outlier, mixed pixels and the farther inside are all passed over.
// The surface's pixels are averaged row by row (rows run along the boundary, one per distance
// inwards), each row's mean depth with its mean position, so a 3-D point is lifted where its
// depth was measured (on a tilted rim, lifting it on the boundary's own ray would flatten the
// fitted plane). Which row the rim is read from is decided over the whole boundary
// (boundary_3d.cc): the row nearest the boundary straddles the object's edge and its depth
// mixes in the background's, a row too far in may be past a bowl's lip, on its inner wall;
// both read farther than the rim.
#pragma once

#include <array>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "scbt/depth/boundary_samples.h"
#include "scbt/depth/depth_options.h"

namespace scbt {

// Depths within this of each other belong to one surface: max(tolerance_floor,
// outlier_sigmas * noise_at_1m * z^2).
double surface_tolerance(const DepthOptions& options, double z);

// The mean depth and image position of one window row's pixels on the nearest surface.
struct RowDepth {
  double z = 0.0;  // metres; 0 when the row has none
  Point pixel;
};

constexpr int kMaxWindowRows = 20;  // DepthOptions::window_length's limit

struct SurfaceDepth {
  double z = 0.0;     // metres; 0 when the window has no surface of min_surface_pixels pixels
  Point pixel;        // the surface's row nearest the boundary: its mean depth and position
  int first_row = 0;  // that row's index
  std::array<RowDepth, kMaxWindowRows> rows{};  // every row's, 0 = the window's first
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
