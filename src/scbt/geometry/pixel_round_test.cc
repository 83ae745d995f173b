#include "scbt/geometry/pixel_round.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace scbt {
namespace {

int library_round(double x) { return static_cast<int>(std::lround(x)); }

TEST(RoundToPixel, RoundsAsTheLibraryDoes) {
  for (const double x :
       {0.0, -0.0, 0.5, -0.5, 1.5, -1.5, 2.5, -2.5, 0.49999999999999994, -0.49999999999999994,
        1e9 + 0.5, -1e9 - 0.5, 2147483646.5, -2147483646.5, 2147483646.4, 4503599627370495.5}) {
    EXPECT_EQ(round_to_pixel(x), library_round(x)) << x;
  }
  std::mt19937 random(1);
  std::uniform_real_distribution<double> coordinate(-5000.0, 5000.0);
  std::uniform_int_distribution<int> whole(-3000, 3000);
  for (int i = 0; i < 100000; ++i) {
    const double x = coordinate(random);
    EXPECT_EQ(round_to_pixel(x), library_round(x)) << x;
    // Halves and their neighbours either side.
    const double half = whole(random) + 0.5;
    for (const double y :
         {half, std::nextafter(half, 0.0), std::nextafter(half, 1e9), std::nextafter(half, -1e9)}) {
      EXPECT_EQ(round_to_pixel(y), library_round(y)) << y;
    }
  }
}

TEST(RoundToPixel, NotANumberAndInfinityGoToTheLibrary) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(round_to_pixel(nan), library_round(nan));
  EXPECT_EQ(round_to_pixel(inf), library_round(inf));
  EXPECT_EQ(round_to_pixel(-inf), library_round(-inf));
}

}  // namespace
}  // namespace scbt
