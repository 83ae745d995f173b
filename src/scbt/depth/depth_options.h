// Options of the boundary's lift to 3-D (boundary_3d.h): how depth is read near the boundary,
// what counts as an outlier, and when the result is trusted.
#pragma once

namespace scbt {

struct DepthOptions {
  double depth_scale = 0.001;  // metres per unit of a 16-bit depth image (ignored for float depth)
  double min_depth = 0.1;      // depths outside [min_depth, max_depth] metres count as missing
  double max_depth = 10.0;

  // Where depth is read: every `sample_step` pixels along the boundary (and at every vertex), a
  // window on the object's side, from `window_offset` to `window_offset + window_length - 1`
  // pixels inwards along the boundary's normal, 2 * window_half_width + 1 pixels across.
  double sample_step = 3.0;
  double window_offset = 1.0;
  int window_length = 4;
  int window_half_width = 1;

  // Depth noise grows with z^2 (structured-light and stereo sensors):
  // sigma(z) = noise_at_1m * z^2 metres. Depths within max(tolerance_floor, outlier_sigmas *
  // sigma(z)) of each other belong to one surface.
  double noise_at_1m = 0.0016;
  double outlier_sigmas = 3.0;
  double tolerance_floor = 0.002;
  int min_surface_pixels = 2;  // a window's nearest surface needs at least this many pixels
  int neighbour_span = 6;      // valid samples each side whose trend a sample's depth must follow

  int plane_iterations = 4;  // robust plane fit: refits on the inliers of the previous fit

  // The result is valid when at least this many samples (and this share of them) have depth.
  int min_valid_points = 8;
  double min_valid_fraction = 0.2;

  // A circle is reported when its RMS distance to the rim is at most this share of its radius.
  double circle_max_relative_rms = 0.03;
  // For such a rim the plane's normal is taken from the outline's ellipse (outline_circle.h)
  // when it is within this angle (degrees) of the depth plane's normal: depth picks one of the
  // ellipse's two solutions, and a larger disagreement means the outline is not a circle's
  // image. 0: the depth plane's normal is kept.
  double outline_normal_max_angle = 10.0;

  // Throws std::invalid_argument naming the first bad value.
  void check() const;
};

}  // namespace scbt
