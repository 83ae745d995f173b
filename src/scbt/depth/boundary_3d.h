// From a tracked image boundary and an aligned depth image to the rim in 3-D: its points, its
// centroid, its plane and, for a near-circular rim, its circle -- what the paper's robot
// experiment needs to pour into a bowl (Qin et al. 2017, Sec. V).
//
// Steps: sample the boundary (every vertex, and every options.sample_step pixels along the edges
// where depth can be read -- near the depth image -- at most about kMaxEdgeSamples of them:
// boundary_samples.h); read each sample's depth as the nearest surface in a small window on the
// object's side (depth_window.h); drop depths that break the curve's local trend
// (curve_outliers.h); lift the rest along the rays of the pixels they were read at; fit a robust
// plane (plane_fit.h); intersect every sample's ray with that plane (so samples whose depth is
// missing still count, with less noise than their own depth); take the arc-length centroid of
// that closed curve (curve_centroid.h); fit a circle to all lifted samples and report it when
// their RMS distance to it is at most circle_max_relative_rms of its radius (all samples, not
// only the vertices: a tracked vertex is the end of a least-squares segment, which lies outside
// an arc).
#pragma once

#include <Eigen/Core>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "scbt/depth/circle_fit.h"
#include "scbt/depth/depth_options.h"
#include "scbt/depth/pinhole_camera.h"
#include "scbt/geometry/polygon.h"

namespace scbt {

struct Boundary3d {
  // True when enough samples had consistent depth (options.min_valid_points and
  // min_valid_fraction) and the plane fit succeeded; centroid, normal and circle are only
  // meaningful then.
  bool valid = false;
  int n_samples = 0;  // boundary samples
  int n_valid = 0;    // samples whose depth passed every check, the plane fit's included

  std::vector<Point> samples;           // the image points where depth was read (pixels)
  std::vector<Eigen::Vector3d> points;  // per sample: its measured 3-D point, NaN when rejected
  std::vector<Eigen::Vector3d> curve;   // per sample: its ray on the fitted plane (NaN if none)

  Eigen::Vector3d centroid{0, 0, 0};  // arc-length centroid of `curve` (metres, camera frame)
  Eigen::Vector3d normal{0, 0, 0};    // the plane's unit normal, towards the camera
  double plane_offset = 0.0;          // the plane is normal . x = plane_offset
  double rms = 0.0;                   // RMS distance of the valid points to the plane (metres)
  CircleFit circle;                   // circle.found only for near-circular rims
};

// `depth` is aligned with the image the boundary was tracked on: CV_16UC1 (units of
// options.depth_scale metres, 0 = no depth) or CV_32FC1 (metres; 0 or NaN = no depth).
// Throws std::invalid_argument for bad options or intrinsics, an empty depth image or one of
// another type. A boundary with fewer than 3 distinct vertices gives an invalid result.
Boundary3d lift_boundary_to_3d(const Polygon& boundary, const cv::Mat& depth,
                               const PinholeIntrinsics& camera, const DepthOptions& options = {});

}  // namespace scbt
