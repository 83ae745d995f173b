#include "scbt/depth/curve_outliers.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "scbt/depth/depth_window.h"

namespace scbt {
namespace {

constexpr int kMaxSpan = 16;

// Median of a small array, sorted in place (insertion sort: at most 120 values).
double small_median(double* values, int count) {
  for (int i = 1; i < count; ++i)
    for (int j = i; j > 0 && values[j - 1] > values[j]; --j) std::swap(values[j - 1], values[j]);
  return count % 2 ? values[count / 2] : 0.5 * (values[count / 2 - 1] + values[count / 2]);
}

// The nearest valid depth on one side (direction +1 or -1) of sample i, 0 if none.
double nearest_valid(const std::vector<double>& z, int i, int direction) {
  const int n = static_cast<int>(z.size());
  for (int step = 1; step < n; ++step) {
    const double value = z[((i + direction * step) % n + n) % n];
    if (value > 0.0) return value;
  }
  return 0.0;
}

// Prediction at sample i from the nearest `span` valid depths on one side (direction +1 or -1):
// a Theil-Sen line over the signed index offset (median slope of all pairs, median intercept),
// so that one bad neighbour does not condemn a good sample.
std::optional<double> side_prediction(const std::vector<double>& z, int i, int direction,
                                      int span) {
  const int n = static_cast<int>(z.size());
  double offsets[kMaxSpan], values[kMaxSpan];
  int count = 0;
  for (int step = 1; step < n && count < span; ++step) {
    const double value = z[((i + direction * step) % n + n) % n];
    if (value <= 0.0) continue;
    offsets[count] = direction * step;
    values[count++] = value;
  }
  if (count < 2) return std::nullopt;
  double slopes[kMaxSpan * (kMaxSpan - 1) / 2];
  int pairs = 0;
  for (int a = 0; a < count; ++a)
    for (int b = a + 1; b < count; ++b)
      slopes[pairs++] = (values[b] - values[a]) / (offsets[b] - offsets[a]);
  const double slope = small_median(slopes, pairs);
  double intercepts[kMaxSpan];
  for (int a = 0; a < count; ++a) intercepts[a] = values[a] - slope * offsets[a];
  return small_median(intercepts, count);  // the line at offset 0
}

}  // namespace

void reject_curve_outliers(const DepthOptions& options, std::vector<double>* depths) {
  if (options.neighbour_span < 2) return;
  const int span = std::min(options.neighbour_span, kMaxSpan);
  const std::vector<double> z = *depths;
  const int n = static_cast<int>(z.size());
  for (int i = 0; i < n; ++i) {
    if (z[i] <= 0.0) continue;
    const double tolerance = surface_tolerance(options, z[i]);
    // Most depths sit between their neighbours: kept without the robust fits.
    const double previous = nearest_valid(z, i, -1), next = nearest_valid(z, i, +1);
    if (previous > 0.0 && next > 0.0 && std::abs(0.5 * (previous + next) - z[i]) <= tolerance)
      continue;
    const auto before = side_prediction(z, i, -1, span);
    const auto after = side_prediction(z, i, +1, span);
    if (!before && !after) continue;
    const bool agrees = (before && std::abs(*before - z[i]) <= tolerance) ||
                        (after && std::abs(*after - z[i]) <= tolerance);
    if (!agrees) (*depths)[i] = 0.0;
  }
}

}  // namespace scbt
