#include "scbt/lines/adaptive_thresholds.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "scbt/lines/boundary_samples.h"

namespace scbt {

void AdaptiveThresholdOptions::check() const {
  if (!(boundary_fraction > 0.0 && boundary_fraction <= 1.0)) {
    throw std::invalid_argument("adaptive threshold boundary_fraction must be in (0, 1]");
  }
  if (!(noise_deviations >= 0.0) || !std::isfinite(noise_deviations)) {
    throw std::invalid_argument("adaptive threshold noise_deviations must be >= 0");
  }
  if (boundary_samples < 3) throw std::invalid_argument("boundary_samples must be >= 3");
  if (!(smoothed_noise > 0.0 && smoothed_noise <= 100.0)) {
    throw std::invalid_argument("adaptive threshold smoothed_noise must be in (0, 100]");
  }
  if (!(search_reach >= 1.0 && search_reach <= 50.0)) {
    throw std::invalid_argument("adaptive threshold search_reach must be in 1..50 px");
  }
}

double edlines_gradient_noise_gain() {
  // |gx| = Sobel x of the smoothed image: separable, derivative (1 0 -1) * g and smoothing
  // (1 2 1) * g, with g = (14 62 104 62 14) / 256 (gaussian_5x5.h).
  static const double gain = [] {
    const double g[5] = {14 / 256.0, 62 / 256.0, 104 / 256.0, 62 / 256.0, 14 / 256.0};
    double d[7] = {0}, s[7] = {0};
    for (int i = 0; i < 5; ++i) {
      d[i] += g[i];
      d[i + 2] -= g[i];
      s[i] += g[i];
      s[i + 1] += 2 * g[i];
      s[i + 2] += g[i];
    }
    double dd = 0, ss = 0;
    for (int i = 0; i < 7; ++i) {
      dd += d[i] * d[i];
      ss += s[i] * s[i];
    }
    return std::sqrt(dd * ss);
  }();
  return gain;
}

double estimate_noise_sigma(const cv::Mat& gray, int row_step) {
  if (gray.type() != CV_8UC1) throw std::invalid_argument("noise estimate needs 8-bit grey");
  if (gray.rows < 3 || gray.cols < 3) return 0.0;
  row_step = std::max(row_step, 1);
  double sum = 0.0;
  long count = 0;
  for (int r = 1; r + 1 < gray.rows; r += row_step) {
    const std::uint8_t* a = gray.ptr<std::uint8_t>(r - 1);
    const std::uint8_t* b = gray.ptr<std::uint8_t>(r);
    const std::uint8_t* c = gray.ptr<std::uint8_t>(r + 1);
    int row_sum = 0;
    for (int x = 1; x + 1 < gray.cols; ++x) {
      const int v = (a[x - 1] + a[x + 1] + c[x - 1] + c[x + 1]) -
                    2 * (a[x] + c[x] + b[x - 1] + b[x + 1]) + 4 * b[x];
      row_sum += std::abs(v);
    }
    sum += row_sum;
    count += gray.cols - 2;
  }
  return count > 0 ? std::sqrt(CV_PI / 2.0) / 6.0 * sum / count : 0.0;
}

double boundary_edge_strength(const cv::Mat& gray, cv::Point offset, const Polygon& boundary,
                              int samples, double reach) {
  if (boundary.size() < 2 || gray.rows < 3 || gray.cols < 3 || samples < 1) return 0.0;
  std::vector<double> strengths;
  strengths.reserve(samples);
  const int reach_px = static_cast<int>(std::ceil(reach));
  std::vector<double> across(2 * reach_px + 3);
  const GreySampler sampler(gray);
  for_each_boundary_sample(boundary, offset, samples, [&](Point p, Point t, Point normal) {
    if (p.x < 1 || p.y < 1 || p.x > gray.cols - 2 || p.y > gray.rows - 2) return;
    // The points read lie within sqrt((reach_px + 1)^2 + 1) px of p: when a wider disc is inside
    // the image, none needs clamping.
    const bool all_inside = sampler.holds_disc(p, reach_px + 2.0);
    // The steepest slope across the boundary, each difference averaged over three points
    // along it to damp noise: the grey levels across it (summed along it) are read once, and
    // the slope at k is the difference of those at k + 1 and k - 1.
    for (int m = -reach_px - 1; m <= reach_px + 1; ++m) {
      const Point at = p + normal * m;
      double sum = 0.0;
      for (int j = -1; j <= 1; ++j) {
        const Point q = at + t * j;
        sum += all_inside ? sampler.inside(q.x, q.y) : sampler.clamped(q.x, q.y);
      }
      across[m + reach_px + 1] = sum;
    }
    double best = 0.0;
    for (int k = 1; k <= 2 * reach_px + 1; ++k) {
      best = std::max(best, std::abs(across[k + 1] - across[k - 1]) / 6.0);
    }
    strengths.push_back(8.0 * best);
  });
  if (strengths.empty()) return 0.0;
  std::nth_element(strengths.begin(), strengths.begin() + strengths.size() / 2, strengths.end());
  return strengths[strengths.size() / 2];
}

double smoothing_for_noise(double noise_sigma, const AdaptiveThresholdOptions& options) {
  // White noise smoothed by a Gaussian of sigma s keeps sigma_n / (2 sqrt(pi) s) of its deviation.
  const double smoothing = noise_sigma / (2.0 * std::sqrt(CV_PI) * options.smoothed_noise);
  // Below 0.5 px a Gaussian hardly smooths: EDLines' own suffices.
  return smoothing >= 0.5 ? std::min(smoothing, 4.0) : 0.0;
}

EdgeThresholds adapt_edge_thresholds(const cv::Mat& gray, cv::Point offset, const Polygon& boundary,
                                     int gradient, int anchor,
                                     const AdaptiveThresholdOptions& options) {
  AdaptiveThresholdOptions without_smoothing = options;
  without_smoothing.smooth_noise = false;
  EdgeThresholds t;
  adapt_to_frame(gray, offset, boundary, gradient, anchor, without_smoothing, nullptr, &t);
  return t;
}

const cv::Mat& adapt_to_frame(const cv::Mat& gray, cv::Point offset, const Polygon& boundary,
                              int gradient, int anchor, const AdaptiveThresholdOptions& options,
                              cv::Mat* smoothed, EdgeThresholds* thresholds, double noise_sigma) {
  EdgeThresholds& t = *thresholds;
  t = EdgeThresholds();
  t.gradient = gradient;
  t.anchor = anchor;
  if (!options.enabled) return gray;
  t.noise_sigma = noise_sigma >= 0.0 ? noise_sigma : estimate_noise_sigma(gray);
  const cv::Mat* image = &gray;
  const double smoothing = smoothing_for_noise(t.noise_sigma, options);
  if (options.smooth_noise && smoothed != nullptr && smoothing > 0.0) {
    t.pre_smoothing = smoothing;
    cv::GaussianBlur(gray, *smoothed, cv::Size(), t.pre_smoothing, t.pre_smoothing,
                     cv::BORDER_REFLECT_101 | cv::BORDER_ISOLATED);
    image = smoothed;
  }
  t.boundary_gradient = boundary_edge_strength(*image, offset, boundary, options.boundary_samples,
                                               options.search_reach);
  // |gx| + |gy| of pure noise: each term has deviation sigma * gain; their sum about sqrt(2)x.
  // A derivative of white noise smoothed to sigma keeps 1/sigma^2 of it: pre-smoothing on top of
  // EDLines' sigma 1 leaves 1 / (1 + s^2).
  const double noise_floor = options.noise_deviations * std::sqrt(2.0) *
                             edlines_gradient_noise_gain() * t.noise_sigma /
                             (1.0 + t.pre_smoothing * t.pre_smoothing);
  // Raising the threshold above the published one for noise loses more of the boundary than it
  // removes noise edges (which the a-contrario validation rejects anyway): noise only limits
  // how far it is lowered.
  double threshold = gradient;
  if (t.boundary_gradient > 0.0) {
    threshold =
        std::min(threshold, std::max(options.boundary_fraction * t.boundary_gradient, noise_floor));
  }
  t.gradient = std::max(1, static_cast<int>(std::lround(threshold)));
  t.anchor = std::max(1, static_cast<int>(std::lround(anchor * threshold / gradient)));
  return *image;
}

}  // namespace scbt
