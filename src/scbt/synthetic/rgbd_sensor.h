// What a real depth sensor does to an exact depth image: noise growing with z^2 (Khoshelham &
// Elberink 2012 measured about 1.5 mm * z^2 for the Kinect), mixed ("flying") pixels across
// depth edges, holes, and a lost stretch of the object's outline (depth often fails right at
// edges), then quantisation to 16-bit units. edge_artefact_sensor() is a sensor whose every
// depth edge is smeared over two pixels and which loses a tenth of the image in blobs.
#pragma once

#include <cstdint>
#include <opencv2/core/mat.hpp>

#include "scbt/geometry/polygon.h"

namespace scbt {

struct DepthSensorOptions {
  double depth_scale = 0.001;      // metres per unit of the 16-bit output
  double noise_at_1m = 0.0016;     // sigma(z) = noise_at_1m * z^2 metres
  double edge_jump = 0.02;         // a step above this between neighbours is a depth edge (m)
  double mixed_pixel_share = 0.7;  // share of depth-edge pixels reading a mix of both sides
  // A mixed pixel reads own + w * (across - own), w uniform in [mixed_weight_min,
  // mixed_weight_max]; `across` is the depth on the edge's other side. A pixel whose footprint
  // straddles the edge reads its coverage-weighted mean: w in [0, 0.5] (its centre is on its
  // own side).
  double mixed_weight_min = 0.2;
  double mixed_weight_max = 0.8;
  // Flying pixels reach this many pixels from a depth edge into each side (a stereo matcher's
  // window, a time-of-flight sensor's filter); in the k-th ring w is divided by k.
  int mixed_pixel_band = 1;
  int hole_blobs = 6;       // random elliptic holes (3-15 px) anywhere in the image
  double hole_share = 0.0;  // and more blobs (3-12 px) until this share of the image has none
  double outline_missing_share = 0.2;  // share of the outline's length whose depth is lost,
  int outline_missing_pieces = 3;      // in this many arcs at random places,
  double outline_missing_width = 8.0;  // this many pixels either side of the outline
  std::uint32_t seed = 1;

  void check() const;  // throws std::invalid_argument naming the first bad value
};

// The sensor a rim on a real depth camera sees at its edges: noise 1.5 mm * z^2, every
// depth-edge pixel mixed by its coverage (w in [0, 0.5]) and the next ring by up to 0.25,
// 10 % of the image lost in blobs, 1 mm units; the outline keeps its 20 % missing.
DepthSensorOptions edge_artefact_sensor(std::uint32_t seed = 1);

// `clean_depth` is CV_32FC1 metres (0 = nothing); `outline` the object's outline in pixels.
// Returns CV_16UC1 in units of depth_scale, 0 where depth is missing; deterministic per
// (seed, frame_index).
cv::Mat apply_depth_sensor(const cv::Mat& clean_depth, const Polygon& outline,
                           const DepthSensorOptions& options, int frame_index = 0);

}  // namespace scbt
