#include "scbt/depth/curve_outliers.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "scbt/depth/depth_window.h"

namespace scbt {
namespace {

constexpr int kMaxSpan = 16;

double median(std::vector<double>* values) {
  auto middle = values->begin() + values->size() / 2;
  std::nth_element(values->begin(), middle, values->end());
  return *middle;
}

// Prediction at sample i from the nearest `span` valid depths on one side (direction +1 or -1):
// a Theil-Sen line over the signed index offset (median slope of all pairs, median intercept),
// so that one bad neighbour does not condemn a good sample.
std::optional<double> side_prediction(const std::vector<double>& z, int i, int direction, int span,
                                      std::vector<double>* scratch) {
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
  scratch->clear();
  for (int a = 0; a < count; ++a)
    for (int b = a + 1; b < count; ++b)
      scratch->push_back((values[b] - values[a]) / (offsets[b] - offsets[a]));
  const double slope = median(scratch);
  scratch->clear();
  for (int a = 0; a < count; ++a) scratch->push_back(values[a] - slope * offsets[a]);
  return median(scratch);  // the line at offset 0
}

}  // namespace

void reject_curve_outliers(const DepthOptions& options, std::vector<double>* depths) {
  if (options.neighbour_span < 2) return;
  const int span = std::min(options.neighbour_span, kMaxSpan);
  std::vector<double> scratch;
  const std::vector<double> z = *depths;
  const int n = static_cast<int>(z.size());
  for (int i = 0; i < n; ++i) {
    if (z[i] <= 0.0) continue;
    const double tolerance = surface_tolerance(options, z[i]);
    const auto before = side_prediction(z, i, -1, span, &scratch);
    const auto after = side_prediction(z, i, +1, span, &scratch);
    if (!before && !after) continue;
    const bool agrees = (before && std::abs(*before - z[i]) <= tolerance) ||
                        (after && std::abs(*after - z[i]) <= tolerance);
    if (!agrees) (*depths)[i] = 0.0;
  }
}

}  // namespace scbt
