#include "scbt/eval/alignment_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <random>

#include "scbt/geometry/polygon_io.h"

namespace scbt {
namespace {

const cv::Size kCanvas(640, 480);

// A random simple (star-shaped) polygon well inside the canvas.
Polygon random_star(std::mt19937& rng) {
  std::uniform_real_distribution<double> cx(200, 440), cy(150, 330), radius(30, 120);
  std::uniform_int_distribution<int> count(3, 12);
  const int n = count(rng);
  const Point centre(cx(rng), cy(rng));
  Polygon polygon;
  for (int i = 0; i < n; ++i) {
    const double angle =
        2.0 * M_PI * (i + 0.5 * std::uniform_real_distribution<double>(0, 1)(rng)) / n;
    const double r = radius(rng);
    polygon.emplace_back(centre.x + r * std::cos(angle), centre.y + r * std::sin(angle));
  }
  return polygon;
}

Polygon square(double x, double y, double side) {
  return {{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}};
}

// E_AL of an axis-aligned square of side s against the same square grown by g on every side,
// derived by hand for the pixel-drawn boundaries: every inner pixel is exactly g from the outer
// boundary, so that mean is g. An outer-boundary pixel beside an inner edge is g away; the pixels
// within g of an outer corner are sqrt(g^2 + d^2) away (d = 1..g-1 on each of the two edges, and
// d = g for the corner itself). The outer boundary has 4 (s + 2g) pixels, so
//   E_AL = g + 4 [ (sqrt(2) g - g) + 2 sum_{d=1}^{g-1} (sqrt(g^2 + d^2) - g) ] / (4 (s + 2g)).
double grown_square_error(int s, int g) {
  double corner = std::sqrt(2.0) * g - g;
  for (int d = 1; d < g; ++d) corner += 2.0 * (std::sqrt(double(g * g + d * d)) - g);
  return g + corner / (s + 2.0 * g);
}

TEST(AlignmentError, PolygonWithItselfIsZero) {
  std::mt19937 rng(1);
  for (int trial = 0; trial < 50; ++trial) {
    const Polygon p = random_star(rng);
    EXPECT_EQ(alignment_error(p, p, kCanvas), 0.0) << format_polygon_line(p);
  }
}

TEST(AlignmentError, SquareGrownByThreePixelsIsAboutThreePointZeroThree) {
  // A 100 px square grown by 3 px: the corner pixels of the bigger square lie up to 3 sqrt(2) px
  // away, lifting its mean from 3 to 3 + 11.11 / 424 = 3.0262. Distances are exact Euclidean
  // (DIST_MASK_PRECISE) stored as float, so 1e-4 is ample; the "about 3.03" is that value.
  const double e = alignment_error(square(200, 150, 100), square(197, 147, 106), kCanvas);
  EXPECT_NEAR(e, grown_square_error(100, 3), 1e-4);
  EXPECT_NEAR(e, 3.03, 0.005);
}

TEST(AlignmentError, GrownSquaresMatchTheHandDerivation) {
  std::mt19937 rng(2);
  std::uniform_int_distribution<int> side(10, 250), grow(1, 10);
  for (int trial = 0; trial < 40; ++trial) {
    const int s = side(rng), g = grow(rng);
    // Both squares fully inside the canvas.
    const int x0 = std::uniform_int_distribution<int>(g + 1, kCanvas.width - s - g - 2)(rng);
    const int y0 = std::uniform_int_distribution<int>(g + 1, kCanvas.height - s - g - 2)(rng);
    const Polygon inner = square(x0, y0, s);
    const Polygon outer = square(x0 - g, y0 - g, s + 2 * g);
    SCOPED_TRACE("side " + std::to_string(s) + " grown by " + std::to_string(g));
    EXPECT_NEAR(alignment_error(inner, outer, kCanvas), grown_square_error(s, g), 1e-4);
    EXPECT_NEAR(alignment_error(outer, inner, kCanvas), grown_square_error(s, g), 1e-4);
  }
}

TEST(AlignmentError, IsSymmetricAndBoundedByATranslation) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> shift(-15, 15);
  for (int trial = 0; trial < 40; ++trial) {
    const Polygon a = random_star(rng);
    const Point v(shift(rng), shift(rng));
    Polygon b = a;
    for (Point& p : b) p += v;
    const double ab = alignment_error(a, b, kCanvas);
    EXPECT_DOUBLE_EQ(ab, alignment_error(b, a, kCanvas));
    EXPECT_GE(ab, 0.0);
    // Every drawn pixel of one boundary is within |v| plus rounding of the other.
    EXPECT_LE(ab, std::hypot(v.x, v.y) + 1.5) << format_polygon_line(a);
  }
}

// The definition computed plainly on the whole canvas, as a reference.
double reference_error(const Polygon& a, const Polygon& b, cv::Size canvas) {
  auto draw = [&](const Polygon& p) {
    cv::Mat image(canvas, CV_8U, cv::Scalar(255));
    std::vector<cv::Point> points;
    for (const Point& q : p) points.emplace_back(cvRound(q.x), cvRound(q.y));
    cv::polylines(image, points, true, cv::Scalar(0), 1, cv::LINE_8);
    return image;
  };
  const cv::Mat ia = draw(a), ib = draw(b);
  cv::Mat da, db;
  cv::distanceTransform(ia, da, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  cv::distanceTransform(ib, db, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  const double a_to_b = cv::mean(db, ia == 0)[0], b_to_a = cv::mean(da, ib == 0)[0];
  return std::max(a_to_b, b_to_a);
}

TEST(AlignmentError, MatchesTheWholeCanvasDefinitionAlsoAtTheBorders) {
  std::mt19937 rng(4);
  // Centres stay on the canvas, so part of each boundary is always visible.
  std::uniform_real_distribution<double> shift(-200, 200);
  for (int trial = 0; trial < 40; ++trial) {
    Polygon a = random_star(rng), b = random_star(rng);
    // Push some boundaries partly off the canvas: only their visible pixels count.
    const Point v(shift(rng), 0.75 * shift(rng));
    for (Point& p : b) p += v;
    EXPECT_NEAR(alignment_error(a, b, kCanvas), reference_error(a, b, kCanvas), 1e-9)
        << format_polygon_line(a) << " / " << format_polygon_line(b);
  }
}

TEST(AlignmentError, FailuresAreInfinite) {
  const Polygon truth = square(100, 100, 50);
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Polygon> bad = {
      {},
      {{10, 10}, {20, 20}},
      {{10, 10}, {20, 20}, {10, 10}},  // 2 distinct points
      {{10, 10}, {20, 20}, {30, 30}},  // collinear: no area
      {{10, 10}, {20, nan}, {30, 10}},
      {{10, 10}, {inf, 20}, {30, 10}},
      square(5000, 5000, 10),  // no pixel on the canvas
  };
  for (const Polygon& p : bad) {
    EXPECT_EQ(alignment_error(p, truth, kCanvas), inf) << format_polygon_line(p);
    EXPECT_EQ(alignment_error(truth, p, kCanvas), inf) << format_polygon_line(p);
  }
}

TEST(AlignmentError, BadResultLinesAreInfiniteWithAReason) {
  const Polygon truth = square(100, 100, 50);
  const double inf = std::numeric_limits<double>::infinity();
  for (const std::string line :
       {"", "   ", "4 100 100 150 100 150 150", "3 1 2 3 4 5 6 7", "x 1 2 3 4 5 6",
        "3 1 2 nan 4 5 6", "3 1 2 inf 4 5 6", "3 100 100 150 100 200 100",
        "4 100 100 150 100 100 100 150 100"}) {
    std::string note;
    EXPECT_EQ(alignment_error_of_line(line, truth, kCanvas, &note), inf) << line;
    EXPECT_FALSE(note.empty()) << line;
  }
  std::string note = "stale";
  EXPECT_EQ(alignment_error_of_line("4 100 100 150 100 150 150 100 150", truth, kCanvas, &note),
            0.0);
  EXPECT_TRUE(note.empty());
}

}  // namespace
}  // namespace scbt
