#include "scbt/lines/edge_blur.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "scbt/lines/boundary_samples.h"

namespace scbt {
namespace {

constexpr int kReach = 7;                // px either side of the boundary
constexpr int kLength = 2 * kReach + 1;  // profile samples
constexpr int kFar = 4;                  // samples at either end that give the step
// The central differences' own spread, added to sigma^2 (a 2 px box: 4 / 12).
constexpr double kDifferenceVariance = 1.0 / 3.0;

// Whether (x, y) lies inside the image, where a bilinear sample needs no clamping.
bool inside(const cv::Mat& gray, const Point& q) {
  return q.x >= 0.0 && q.y >= 0.0 && q.x <= gray.cols - 1.0 && q.y <= gray.rows - 1.0;
}

// The grey-level step the profile crosses: the mean of its kFar samples at the far end less that
// at the near end.
double profile_step(const std::array<double, kLength>& profile) {
  double near = 0.0, far = 0.0;
  for (int i = 0; i < kFar; ++i) {
    near += profile[i];
    far += profile[kLength - 1 - i];
  }
  return (far - near) / kFar;
}

// The spread of the step the profile crosses, or -1 when it crosses none clearly.
double profile_sigma(const std::array<double, kLength>& profile, double min_step) {
  const double step = profile_step(profile);
  if (!(std::abs(step) >= min_step)) return -1.0;
  const double sign = step > 0.0 ? 1.0 : -1.0;
  std::array<double, kLength - 2> slope;
  for (int i = 0; i + 2 < kLength; ++i) slope[i] = sign * (profile[i + 2] - profile[i]) / 2.0;
  const int peak = static_cast<int>(std::max_element(slope.begin(), slope.end()) - slope.begin());
  if (peak < 2 || peak + 2 >= static_cast<int>(slope.size()) || !(slope[peak] > 0.0)) return -1.0;
  const double ratio = (slope[peak - 2] + slope[peak + 2]) / (2.0 * slope[peak]);
  // Beyond these the ratio no longer resolves the spread: an edge sharper than the first is read
  // as the first; a flat slope (no peak) is no step.
  constexpr double kSharpest = 0.01, kFlattest = 0.99;
  if (!(ratio < kFlattest)) return -1.0;
  return std::sqrt(-2.0 / std::log(std::max(ratio, kSharpest)));
}

// The total spread (px^2) of a focused camera's step as the detector's gradient sees it: its own
// smoothing, the camera's, and the central differences'.
double sharp_spread(double detector_sigma, const EdgeBlurOptions& options) {
  return detector_sigma * detector_sigma +
         (options.sharp_sigma * options.sharp_sigma + kDifferenceVariance);
}

}  // namespace

void EdgeBlurOptions::check() const {
  if (!(sharp_sigma > 0.0 && sharp_sigma <= 10.0)) {
    throw std::invalid_argument("edge blur sharp_sigma must be in (0, 10] px, got " +
                                std::to_string(sharp_sigma));
  }
  if (!(min_gain > 0.0 && min_gain <= max_gain && max_gain <= 1.0)) {
    throw std::invalid_argument("edge blur gains must satisfy 0 < min_gain <= max_gain <= 1");
  }
  if (!(update_weight > 0.0 && update_weight <= 1.0)) {
    throw std::invalid_argument("edge blur update_weight must be in (0, 1], got " +
                                std::to_string(update_weight));
  }
  if (measure_every < 1 || measure_every > 1000) {
    throw std::invalid_argument("edge blur measure_every must be in 1..1000, got " +
                                std::to_string(measure_every));
  }
  if (samples < 1 || samples > 10000 || min_edges < 1 || min_edges > samples) {
    throw std::invalid_argument("edge blur needs 1 <= min_edges <= samples <= 10000");
  }
}

double estimate_edge_blur(const cv::Mat& gray, cv::Point window_tl, const Polygon& boundary,
                          double min_step, const EdgeBlurOptions& options) {
  if (gray.empty() || gray.type() != CV_8UC1 || gray.rows < 2 || gray.cols < 2 ||
      boundary.size() < 3) {
    return -1.0;
  }
  std::vector<double> sigmas;
  sigmas.reserve(static_cast<size_t>(options.samples));
  std::array<double, kLength> profile;
  const GreySampler sampler(gray);
  // The spread of the step the boundary crosses at p, if it crosses one clearly.
  const auto measure = [&](Point p, Point t, Point normal) {
    // The points read lie within sqrt(kReach^2 + 1) px of p: when a wider disc is inside the
    // image, none needs checking or clamping.
    const bool all_inside = sampler.holds_disc(p, kReach + 1.0);
    // profile[k], kReach - k px along the normal (the step's sign does not matter): false when a
    // point is outside the image.
    const auto read = [&](int k) {
      const Point across = p + normal * static_cast<double>(kReach - k);
      double sum = 0.0;
      for (int lane = -1; lane <= 1; ++lane) {
        const Point q = across + t * static_cast<double>(lane);
        if (all_inside) {
          sum += sampler.inside(q.x, q.y);
        } else {
          if (!inside(gray, q)) return false;
          sum += sampler.clamped(q.x, q.y);
        }
      }
      profile[k] = sum / 3.0;
      return true;
    };
    // The ends first: where they differ by less than a clear step, the middle is not read.
    for (int k = 0; k < kFar; ++k) {
      if (!read(k) || !read(kLength - 1 - k)) return;
    }
    if (!(std::abs(profile_step(profile)) >= min_step)) return;
    for (int k = kFar; k < kLength - kFar; ++k) {
      if (!read(k)) return;
    }
    const double sigma = profile_sigma(profile, min_step);
    if (sigma > 0.0) sigmas.push_back(sigma);
  };
  for_each_boundary_sample(boundary, window_tl, options.samples, measure);
  if (static_cast<int>(sigmas.size()) < options.min_edges) return -1.0;
  const auto middle = sigmas.begin() + static_cast<std::ptrdiff_t>(sigmas.size() / 2);
  std::nth_element(sigmas.begin(), middle, sigmas.end());
  return *middle;
}

double edge_blur_gain(double sigma, double detector_sigma, const EdgeBlurOptions& options) {
  if (!(sigma > 0.0)) return 1.0;
  const double gain = std::sqrt(sharp_spread(detector_sigma, options) /
                                (detector_sigma * detector_sigma + sigma * sigma));
  if (gain > options.max_gain) return 1.0;
  return std::max(gain, options.min_gain);
}

double edge_blur_anchor_gain(double sigma, double detector_sigma, const EdgeBlurOptions& options) {
  const double gain = edge_blur_gain(sigma, detector_sigma, options);
  if (gain >= 1.0) return 1.0;
  // The gradient across a step spread by s^2 (all spreads added) is a Gaussian of that variance:
  // its peak exceeds the neighbours 1 px away by a share 1 - exp(-1 / (2 s^2)) of itself.
  const double sharp = sharp_spread(detector_sigma, options);
  const double spread = sharp / (gain * gain);  // as edge_blur_gain saw it, within its limits
  const double share = 1.0 - std::exp(-1.0 / (2.0 * spread));
  const double sharp_share = 1.0 - std::exp(-1.0 / (2.0 * sharp));
  return gain * share / sharp_share;
}

}  // namespace scbt
