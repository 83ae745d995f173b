// The long-term shape the boundary choice weighs candidates against.
#include "scbt/tracker/shape_memory.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace scbt {
namespace {

constexpr double kPi = 3.14159265358979323846;

Polygon ellipse(Point center, double a, double b, double tilt, int n = 48) {
  Polygon p;
  for (int i = 0; i < n; ++i) {
    const double t = 2.0 * kPi * i / n;
    const Point local(a * std::cos(t), b * std::sin(t));
    p.push_back(center + Point(local.x * std::cos(tilt) - local.y * std::sin(tilt),
                               local.x * std::sin(tilt) + local.y * std::cos(tilt)));
  }
  return p;
}

Polygon square(Point center, double half) {
  return {center + Point(-half, -half), center + Point(half, -half), center + Point(half, half),
          center + Point(-half, half)};
}

TEST(ShapeMemory, IsInvalidUntilShownAValidBoundary) {
  ShapeMemory memory;
  EXPECT_FALSE(memory.descriptor().valid);
  memory.remember({Point(0, 0), Point(10, 0), Point(20, 0)});  // no area
  EXPECT_FALSE(memory.descriptor().valid);
  memory.remember(square(Point(50, 50), 10));
  EXPECT_TRUE(memory.descriptor().valid);
  EXPECT_NEAR(shape_distance(memory.descriptor(), affine_shape_descriptor(square({0, 0}, 3))), 0.0,
              1e-9);
}

// A rim seen from another angle (an ellipse of another aspect and tilt, elsewhere, at another
// size) is the same affine shape: the memory does not move.
TEST(ShapeMemory, KeepsTheShapeOfARimSeenFromAnotherAngle) {
  ShapeMemory memory(0.5);
  memory.restart(ellipse(Point(300, 200), 80, 80, 0.0));
  const ShapeDescriptor circle = memory.descriptor();
  for (int frame = 0; frame < 20; ++frame) {
    memory.remember(ellipse(Point(300 + 5 * frame, 200), 80 + frame, 30 + 2 * frame, 0.1 * frame));
  }
  EXPECT_LT(shape_distance(memory.descriptor(), circle), 1e-3);
}

// The magnitudes move linearly: one step goes `rate` of the way to the new shape, and a shape
// shown long enough is taken over.
TEST(ShapeMemory, MovesByTheRateTowardsEachBoundaryShown) {
  const Polygon round = ellipse(Point(100, 100), 40, 25, 0.3);
  const Polygon box = square(Point(100, 100), 30);
  const double apart = shape_distance(affine_shape_descriptor(round), affine_shape_descriptor(box));
  ASSERT_GT(apart, 0.02);
  ShapeMemory memory(0.05);
  memory.restart(round);
  memory.remember(box);
  EXPECT_NEAR(shape_distance(memory.descriptor(), affine_shape_descriptor(round)), 0.05 * apart,
              1e-12);
  EXPECT_NEAR(shape_distance(memory.descriptor(), affine_shape_descriptor(box)), 0.95 * apart,
              1e-12);
  for (int frame = 1; frame < 200; ++frame) memory.remember(box);
  EXPECT_LT(shape_distance(memory.descriptor(), affine_shape_descriptor(box)), 1e-4 * apart);
  // restart forgets.
  memory.restart(round);
  EXPECT_NEAR(shape_distance(memory.descriptor(), affine_shape_descriptor(round)), 0.0, 1e-15);
}

TEST(ShapeMemory, RejectsARateOutsideZeroToOne) {
  EXPECT_THROW(ShapeMemory(0.0), std::invalid_argument);
  EXPECT_THROW(ShapeMemory(1.5), std::invalid_argument);
  EXPECT_THROW(ShapeMemory(std::nan("")), std::invalid_argument);
  EXPECT_NO_THROW(ShapeMemory(1.0));
}

}  // namespace
}  // namespace scbt
