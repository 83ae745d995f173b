#include "scbt/eval/success_curve.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "scbt/eval/alignment_error.h"

namespace scbt {

SuccessCurve success_curve(const std::vector<double>& errors, double max_threshold, double step) {
  if (!std::isfinite(step) || !std::isfinite(max_threshold) || step <= 0.0 ||
      step > max_threshold) {
    throw std::invalid_argument("success curve: need 0 < step <= max threshold, got step " +
                                std::to_string(step) + ", max " + std::to_string(max_threshold));
  }
  // Sorting once makes each rate a binary search; NaN (a failure) sorts as +infinity.
  std::vector<double> sorted;
  sorted.reserve(errors.size());
  for (double e : errors)
    sorted.push_back(std::isnan(e) ? std::numeric_limits<double>::infinity() : e);
  std::sort(sorted.begin(), sorted.end());
  SuccessCurve curve;
  const int steps = static_cast<int>(std::floor(max_threshold / step + 1e-9));
  for (int i = 0; i <= steps; ++i) {
    const double threshold = i * step;
    const size_t below = std::lower_bound(sorted.begin(), sorted.end(), threshold) - sorted.begin();
    curve.thresholds.push_back(threshold);
    curve.rates.push_back(sorted.empty() ? 0.0 : static_cast<double>(below) / sorted.size());
  }
  return curve;
}

double area_under_curve(const SuccessCurve& curve) {
  const size_t n = std::min(curve.thresholds.size(), curve.rates.size());
  if (n < 2) return 0.0;
  const double range = curve.thresholds[n - 1] - curve.thresholds[0];
  if (range <= 0.0) return 0.0;
  double area = 0.0;
  for (size_t i = 1; i < n; ++i) {
    area += 0.5 * (curve.rates[i] + curve.rates[i - 1]) *
            (curve.thresholds[i] - curve.thresholds[i - 1]);
  }
  return area / range;
}

double success_auc(const std::vector<double>& errors, double max_threshold) {
  if (!(max_threshold > 0.0) || !std::isfinite(max_threshold)) {
    throw std::invalid_argument("success AUC: max threshold " + std::to_string(max_threshold) +
                                " must be positive");
  }
  if (errors.empty()) return 0.0;
  double sum = 0.0;
  for (double e : errors) {
    // NaN fails the comparison and counts as a failure, like +infinity.
    if (e < max_threshold) sum += 1.0 - std::max(0.0, e) / max_threshold;
  }
  return sum / static_cast<double>(errors.size());
}

ErrorStats error_stats(const std::vector<double>& errors) {
  ErrorStats stats;
  stats.frames = static_cast<int>(errors.size());
  double sum = 0.0;
  std::vector<double> all;
  all.reserve(errors.size());
  for (double e : errors) {
    if (std::isfinite(e)) {
      sum += e;
      all.push_back(e);
    } else {
      ++stats.failures;
      all.push_back(std::numeric_limits<double>::infinity());
    }
  }
  const int scored = stats.frames - stats.failures;
  stats.mean = scored > 0 ? sum / scored : std::numeric_limits<double>::quiet_NaN();
  if (all.empty()) {
    stats.median = std::numeric_limits<double>::quiet_NaN();
  } else {
    std::sort(all.begin(), all.end());
    const size_t n = all.size();
    stats.median = n % 2 == 1 ? all[n / 2] : 0.5 * (all[n / 2 - 1] + all[n / 2]);
  }
  stats.success_5 = success_rate(errors, 5.0);
  stats.success_10 = success_rate(errors, 10.0);
  stats.success_20 = success_rate(errors, 20.0);
  stats.auc = success_auc(errors);
  return stats;
}

}  // namespace scbt
