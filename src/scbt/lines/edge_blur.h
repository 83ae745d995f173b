// How blurred the tracked object's edges are, and how much that lowers the detector's response to
// them. A defocused or smoothed camera spreads a step edge over sigma px: its steepest gradient
// after EDLines' own smoothing (sigma 1) falls as 1 / sqrt(1 + sigma^2), so that at the published
// thresholds a blurred boundary breaks into fragments (or vanishes) while the strongest edges of
// the background remain, and the grouping closes the wrong cycle with confidence.
#pragma once

#include <opencv2/core/mat.hpp>
#include <opencv2/core/types.hpp>

#include "scbt/geometry/polygon.h"

namespace scbt {

struct EdgeBlurOptions {
  // Scale the detector's thresholds down by edge_blur_gain of the last tracked boundary's blur.
  bool adapt = true;
  // The edge spread (Gaussian sigma, px) of a focused camera, whose frames the published
  // thresholds suit: optics and demosaicing spread a step over about a pixel.
  double sharp_sigma = 1.0;
  // The gain stops here (a spread of about 5 px: beyond it little of an edge is left to find).
  double min_gain = 0.25;
  // A gain above this (a spread under about 2 px as estimate_edge_blur reads it; focused cameras
  // read 1.0-1.8, a fast one's own motion blur up to about 2) is taken as 1: the published
  // thresholds stay where they serve, and a small change of threshold changes which of two
  // near-equal cycles a sequence follows more than it finds edges.
  double max_gain = 0.68;
  // Weight of a new estimate in the running one: a camera's blur changes over frames, one
  // frame's estimate is noisy.
  double update_weight = 0.25;
  // Confidently tracked frames from one estimate to the next: blur changes over many frames, an
  // estimate costs as much as a few percent of a frame. The running estimate keeps its pace (its
  // weight is that of update_weight applied on each frame).
  int measure_every = 2;
  // Points read along the boundary, of which at least min_edges must cross a clear step.
  int samples = 32;
  int min_edges = 8;

  // Throws std::invalid_argument naming the first bad value.
  void check() const;
};

// The median edge spread (Gaussian sigma, px) across `boundary` (frame coordinates) in `gray`
// (8-bit grey, the window of the frame whose top-left corner is `window_tl`): at points spaced
// evenly along it, the grey profile across it (-7..7 px, three parallel lines averaged) whose
// far sides differ by at least `min_step` grey levels; each profile's slope, read by central
// differences, falls from its peak over 2 px by exp(-2 / sigma^2) for a Gaussian-blurred step.
// The central differences add 1/3 px^2 to sigma^2; a spread of 3 px or more is read up to 15 %
// short (its tails leave the profile). -1 when fewer than `options.min_edges`
// points cross such a step (the boundary is not there, or has no clear edges).
double estimate_edge_blur(const cv::Mat& gray, cv::Point window_tl, const Polygon& boundary,
                          double min_step, const EdgeBlurOptions& options);

// The factor by which an edge's steepest gradient after the detector's own smoothing
// (`detector_sigma`) is below a focused camera's (options.sharp_sigma), for an edge spread
// `sigma` as estimate_edge_blur measures it: 1 for a sharp edge (or sigma < 0: unknown) and for
// a gain above options.max_gain, at least options.min_gain.
double edge_blur_gain(double sigma, double detector_sigma, const EdgeBlurOptions& options);

// The same for EDLines' anchor test, a pixel's gradient above its neighbours' across the edge: a
// spread edge's gradient is both lower and flatter, so this falls about as the cube of
// edge_blur_gain (1 where that is 1).
double edge_blur_anchor_gain(double sigma, double detector_sigma, const EdgeBlurOptions& options);

}  // namespace scbt
