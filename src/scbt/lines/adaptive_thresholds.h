// EDLines' thresholds adapted to the frame: the published gradient threshold 36 and anchor
// threshold 8 suit a well-exposed, sharp, clean image; in a dim, low-contrast or blurred frame
// the object's own boundary falls below them, and in a noisy one noise ridges pass them. Per
// frame the thresholds are lowered to a fraction of the gradient the tracked boundary itself
// shows (so that its edges stay detectable, whatever the exposure or focus), never below what
// the estimated sensor noise produces by chance, and never above the published values. The
// anchor threshold scales with the gradient threshold.
#pragma once

#include <opencv2/core/mat.hpp>

#include "scbt/geometry/polygon.h"

namespace scbt {

struct AdaptiveThresholdOptions {
  // On every frame. Off by default: lowering the thresholds where the published ones work lets
  // clutter into the band (docs/dev/camera-log-2026-12-02.md).
  bool enabled = false;
  // Only on a weak frame (when `enabled` is off): a frame whose search with the published
  // thresholds finds no boundary, or one below the tracking confidence, is searched again with
  // the adapted thresholds (and smoothing, below); its boundary is taken when trusted and, since
  // lowered thresholds close many more cycles, of the reference shape (LossOptions::
  // match_shape_distance). A video the published thresholds serve is tracked as without it.
  bool retry_weak_frames = true;
  // ... and the setting (published or adapted) that won a weak frame's retry is the one tried
  // first on the next frames, the other one being the retry: a dim or noisy video then runs one
  // search per frame again, and switches back when the published thresholds win a weak frame.
  bool keep_retry_winner = true;
  // The gradient threshold may drop to this fraction of the boundary's median edge strength.
  double boundary_fraction = 0.5;
  // ... but stays at least this many standard deviations of the gradient that noise alone gives.
  double noise_deviations = 3.0;
  int boundary_samples = 48;  // points along the boundary where its edge strength is read
  double search_reach = 6.0;  // px on either side of the boundary searched for its edge
  // Noise-dependent smoothing: when the estimated noise is more than EDLines' own smoothing
  // (sigma 1) was made for, the window is first smoothed with the Gaussian that leaves about
  // `smoothed_noise` grey levels of white noise (sigma_n / (2 sqrt(pi) s)), so that edge walks
  // follow the boundary instead of noise ridges.
  bool smooth_noise = true;
  double smoothed_noise = 2.0;

  // Throws std::invalid_argument naming the first bad value.
  void check() const;
};

struct EdgeThresholds {
  int gradient = 36;
  int anchor = 8;
  double noise_sigma = 0.0;        // estimated noise of the grey image (grey levels)
  double boundary_gradient = 0.0;  // the boundary's median edge strength, EDLines' units
  double pre_smoothing = 0.0;      // sigma of the smoothing applied before detection (0: none)
};

// Immerkær's fast noise estimate (1996): the mean absolute response of the Laplacian difference
// mask [1 -2 1; -2 4 -2; 1 -2 1] times sqrt(pi / 2) / 6, over every `row_step`-th row.
double estimate_noise_sigma(const cv::Mat& gray, int row_step = 2);

// Median over points along `boundary` (full-image coordinates; `gray` is the window at `offset`)
// of the steepest intensity slope across the boundary within `reach` px, in the units of
// EDLines' |gx| + |gy| (Sobel on the smoothed image: 8 x the slope per pixel of a ramp).
// 0 when no sample falls inside the window.
double boundary_edge_strength(const cv::Mat& gray, cv::Point offset, const Polygon& boundary,
                              int samples, double reach);

// The thresholds for this frame from the published ones (`gradient`, `anchor`).
EdgeThresholds adapt_edge_thresholds(const cv::Mat& gray, cv::Point offset, const Polygon& boundary,
                                     int gradient, int anchor,
                                     const AdaptiveThresholdOptions& options);

// The same, first smoothing `gray` into *smoothed when options.smooth_noise and the noise call
// for it. Returns the image to detect on: *smoothed, or gray. `noise_sigma`: the camera's noise
// when already known (grey levels); < 0: estimated on `gray`.
const cv::Mat& adapt_to_frame(const cv::Mat& gray, cv::Point offset, const Polygon& boundary,
                              int gradient, int anchor, const AdaptiveThresholdOptions& options,
                              cv::Mat* smoothed, EdgeThresholds* thresholds,
                              double noise_sigma = -1.0);

// The sigma (px) of the Gaussian applied before detection for noise of `noise_sigma` grey levels
// (AdaptiveThresholdOptions::smooth_noise; 0: none needed).
double smoothing_for_noise(double noise_sigma, const AdaptiveThresholdOptions& options);

// Standard deviation of EDLines' |gx| (Sobel after its 5x5 Gaussian) for unit white noise.
double edlines_gradient_noise_gain();

}  // namespace scbt
