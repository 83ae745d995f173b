// Success-rate curves (paper §IV-A) and the summary numbers derived from a list of E_AL values.
#pragma once

#include <vector>

namespace scbt {

// Success rate at each threshold e_p: the share of frames with E_AL < e_p.
struct SuccessCurve {
  std::vector<double> thresholds;  // increasing, in pixels
  std::vector<double> rates;       // same length, in 0..1, non-decreasing
};

// The curve over e_p = 0, step, 2*step, ..., max_threshold (the paper: 0..50 px, step 1).
// Throws std::invalid_argument unless 0 < step <= max_threshold and both are finite.
SuccessCurve success_curve(const std::vector<double>& errors, double max_threshold = 50.0,
                           double step = 1.0);

// Area under a sampled curve by the trapezoid rule, divided by the threshold range (0 for fewer
// than two points). Within step / max_threshold of success_auc for a curve from success_curve.
double area_under_curve(const SuccessCurve& curve);

// The exact normalised area under the continuous success curve over e_p = 0..max_threshold:
// (1 / max) * integral of rate(e) de = the mean over frames of max(0, 1 - E_AL / max).
// 1 when every error is 0, 0 when every frame fails or errs by max_threshold or more; 0 for an
// empty list. Throws std::invalid_argument unless max_threshold is positive and finite.
double success_auc(const std::vector<double>& errors, double max_threshold = 50.0);

// The numbers reported per (tracker, sequence). Failures are infinite (or NaN) errors.
struct ErrorStats {
  int frames = 0;
  int failures = 0;        // frames with a non-finite E_AL
  double mean = 0.0;       // mean E_AL over the scored (finite) frames; NaN when none
  double median = 0.0;     // median over all frames, failures counting as +infinity
  double success_5 = 0.0;  // success rate at e_p = 5, 10 and 20 px
  double success_10 = 0.0;
  double success_20 = 0.0;
  double auc = 0.0;  // success_auc(errors) over 0..50 px, 0..1
};

ErrorStats error_stats(const std::vector<double>& errors);

}  // namespace scbt
