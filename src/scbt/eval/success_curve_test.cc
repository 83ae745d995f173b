#include "scbt/eval/success_curve.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace scbt {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Random errors mixing small and large values, infinities and NaNs.
std::vector<double> random_errors(std::mt19937& rng) {
  std::uniform_int_distribution<int> size(0, 300), kind(0, 9);
  std::exponential_distribution<double> magnitude(0.1);
  std::vector<double> errors(size(rng));
  for (double& e : errors) {
    const int k = kind(rng);
    e = k == 0 ? kInf : k == 1 ? std::numeric_limits<double>::quiet_NaN() : magnitude(rng);
  }
  return errors;
}

TEST(SuccessCurve, IsMonotoneAndMatchesACount) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 100; ++trial) {
    const std::vector<double> errors = random_errors(rng);
    const SuccessCurve curve = success_curve(errors);
    ASSERT_EQ(curve.thresholds.size(), 51u);
    ASSERT_EQ(curve.rates.size(), 51u);
    EXPECT_EQ(curve.thresholds.front(), 0.0);
    EXPECT_EQ(curve.thresholds.back(), 50.0);
    for (size_t i = 0; i < curve.rates.size(); ++i) {
      if (i > 0) {
        EXPECT_GE(curve.rates[i], curve.rates[i - 1]);
      }
      const double below = std::count_if(errors.begin(), errors.end(),
                                         [&](double e) { return e < curve.thresholds[i]; });
      EXPECT_DOUBLE_EQ(curve.rates[i], errors.empty() ? 0.0 : below / errors.size());
    }
  }
}

TEST(SuccessCurve, TrapezoidAreaIsWithinOneStepOfTheExactArea) {
  std::mt19937 rng(12);
  for (int trial = 0; trial < 100; ++trial) {
    const std::vector<double> errors = random_errors(rng);
    const double exact = success_auc(errors);
    EXPECT_GE(exact, 0.0);
    EXPECT_LE(exact, 1.0);
    EXPECT_NEAR(area_under_curve(success_curve(errors)), exact, 1.0 / 50.0 + 1e-12);
  }
}

TEST(SuccessCurve, AreaLimits) {
  EXPECT_DOUBLE_EQ(success_auc({0.0, 0.0, 0.0}), 1.0);
  EXPECT_DOUBLE_EQ(success_auc({kInf, 50.0, 80.0}), 0.0);
  EXPECT_DOUBLE_EQ(success_auc({25.0}), 0.5);
  EXPECT_DOUBLE_EQ(success_auc({}), 0.0);
  EXPECT_THROW(success_auc({1.0}, 0.0), std::invalid_argument);
  EXPECT_THROW(success_curve({1.0}, 50.0, 0.0), std::invalid_argument);
  EXPECT_THROW(success_curve({1.0}, 5.0, 10.0), std::invalid_argument);
}

TEST(ErrorStats, CountsFailuresAndTakesTheirMedianAsInfinite) {
  std::mt19937 rng(13);
  for (int trial = 0; trial < 100; ++trial) {
    const std::vector<double> errors = random_errors(rng);
    const ErrorStats stats = error_stats(errors);
    int failures = 0;
    double sum = 0.0;
    std::vector<double> sorted;
    for (double e : errors) {
      if (std::isfinite(e)) {
        sum += e;
      } else {
        ++failures;
      }
      sorted.push_back(std::isfinite(e) ? e : kInf);
    }
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(stats.frames, static_cast<int>(errors.size()));
    EXPECT_EQ(stats.failures, failures);
    if (failures < stats.frames) {
      EXPECT_NEAR(stats.mean, sum / (stats.frames - failures), 1e-9);
    } else {
      EXPECT_TRUE(std::isnan(stats.mean));
    }
    if (!sorted.empty()) {
      // At least half the frames are <= the median and at least half are >= it.
      const auto le =
          std::count_if(sorted.begin(), sorted.end(), [&](double e) { return e <= stats.median; });
      const auto ge =
          std::count_if(sorted.begin(), sorted.end(), [&](double e) { return e >= stats.median; });
      EXPECT_GE(2 * le, static_cast<long>(sorted.size()));
      EXPECT_GE(2 * ge, static_cast<long>(sorted.size()));
    }
    EXPECT_LE(stats.success_5, stats.success_10);
    EXPECT_LE(stats.success_10, stats.success_20);
    EXPECT_DOUBLE_EQ(stats.auc, success_auc(errors));
  }
}

}  // namespace
}  // namespace scbt
