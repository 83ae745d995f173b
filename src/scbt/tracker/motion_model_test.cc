#include "scbt/tracker/motion_model.h"

#include <gtest/gtest.h>

#include <cmath>

namespace scbt {
namespace {

Polygon square(Point centre, double half) {
  return {centre + Point(-half, -half), centre + Point(half, -half), centre + Point(half, half),
          centre + Point(-half, half)};
}

TEST(MotionModel, CentroidOfAreaNotOfVertices) {
  // Extra vertices crowded on one edge move the vertex mean but not the area's centroid.
  const Polygon p = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {10, 0}, {10, 10}, {0, 10}};
  const Point c = area_centroid(p);
  EXPECT_NEAR(c.x, 5.0, 1e-12);
  EXPECT_NEAR(c.y, 5.0, 1e-12);
}

TEST(MotionModel, AtRestUntilItHasSeenMotion) {
  MotionModel model;
  model.reset();
  model.update(square({50, 50}, 10));
  Polygon predicted;
  model.predict(square({50, 50}, 10), true, &predicted);
  EXPECT_EQ(predicted, square({50, 50}, 10));
  EXPECT_DOUBLE_EQ(model.predicted_area_ratio(), 1.0);
}

TEST(MotionModel, ExtrapolatesTranslationAndGrowthAcrossHeldFrames) {
  MotionModel model;
  model.reset();
  model.update(square({50, 50}, 10));
  model.update(square({53, 46}, 11));  // moved (3, -4), area x 1.21
  Polygon predicted;
  model.predict(square({53, 46}, 11), false, &predicted);
  const Polygon moved = square({56, 42}, 11);
  for (size_t i = 0; i < moved.size(); ++i) EXPECT_NEAR(cv::norm(predicted[i] - moved[i]), 0, 1e-9);
  EXPECT_NEAR(model.predicted_area_ratio(), 1.21, 1e-9);
  model.predict(square({53, 46}, 11), true, &predicted);
  const Polygon grown = square({56, 42}, 12.1);
  for (size_t i = 0; i < grown.size(); ++i) EXPECT_NEAR(cv::norm(predicted[i] - grown[i]), 0, 1e-9);
  // A held frame: two frames' worth of motion by the next one.
  model.update_held();
  model.predict(square({53, 46}, 11), false, &predicted);
  const Polygon twice = square({59, 38}, 11);
  for (size_t i = 0; i < twice.size(); ++i) EXPECT_NEAR(cv::norm(predicted[i] - twice[i]), 0, 1e-9);
  EXPECT_NEAR(model.predicted_area_ratio(), 1.21 * 1.21, 1e-9);
  // The velocity after the gap is measured over both frames.
  model.update(square({59, 38}, 11));
  model.predict(square({59, 38}, 11), false, &predicted);
  EXPECT_NEAR(area_centroid(predicted).x, 62.0, 1e-9);
  model.reset();
  model.update(square({0, 0}, 5));
  model.predict(square({0, 0}, 5), true, &predicted);
  EXPECT_NEAR(area_centroid(predicted).x, 0.0, 1e-12);
}

// Half sizes whose areas shrink by 10 %, 20 % and 5 % per frame: the slowest, 5 %, is followed
// (also over a held frame); one growing frame among them, or fewer than three rates, follows none.
TEST(MotionModel, SustainedShrinkFollowsOnlyASteadyShrinking) {
  MotionModel model;
  double half = 20.0;
  model.update(square({50, 50}, half));
  for (const double area_ratio : {0.9, 0.8}) {
    EXPECT_DOUBLE_EQ(model.sustained_shrink_ratio(), 1.0);
    half *= std::sqrt(area_ratio);
    model.update(square({50, 50}, half));
  }
  EXPECT_DOUBLE_EQ(model.sustained_shrink_ratio(), 1.0);
  half *= std::sqrt(0.95);
  model.update(square({50, 50}, half));
  EXPECT_NEAR(model.sustained_shrink_ratio(), 0.95, 1e-9);
  model.update_held();
  EXPECT_NEAR(model.sustained_shrink_ratio(), 0.95 * 0.95, 1e-9);
  half *= 1.01;
  model.update(square({50, 50}, half));
  EXPECT_DOUBLE_EQ(model.sustained_shrink_ratio(), 1.0);
  model.reset();
  model.update(square({50, 50}, 20.0));
  EXPECT_DOUBLE_EQ(model.sustained_shrink_ratio(), 1.0);
}

}  // namespace
}  // namespace scbt
