// Property tests of our EDLines over seeded random synthetic images: true straight edges are
// found, flat noise gives nothing, a window gives what the whole image gives inside it, the band
// keeps what lies in it, results are deterministic, odd images do not crash, and most of OpenCV
// EdgeDrawing's segments are found too.
#include "scbt/lines/edlines.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <opencv2/imgproc.hpp>
#include <random>
#include <stdexcept>
#include <vector>

#include "scbt/lines/band_mask.h"
#include "scbt/lines/line_detector.h"
#include "scbt/synthetic/scene.h"

namespace scbt {
namespace {

double angle_between(const Segment& s, const Segment& t) {
  const Point d1 = s.b - s.a, d2 = t.b - t.a;
  const double c = std::abs(d1.dot(d2)) / (cv::norm(d1) * cv::norm(d2));
  return std::acos(std::min(1.0, c)) * 180.0 / M_PI;
}

// Length of `side` covered by segments whose endpoints both lie within `tolerance` of its line
// and whose direction is within `max_angle` degrees of it (the union of their projections on it).
double covered_length(const Segment& side, const std::vector<Segment>& segments, double tolerance,
                      double max_angle = 90.0) {
  const double length = side.length();
  const Point dir = (side.b - side.a) * (1.0 / length);
  auto off_line = [&](const Point& p) { return std::abs((p - side.a).cross(dir)); };
  std::vector<std::pair<double, double>> spans;
  for (const Segment& s : segments) {
    if (off_line(s.a) > tolerance || off_line(s.b) > tolerance || s.length() < 1e-9 ||
        angle_between(s, side) > max_angle) {
      continue;
    }
    double t0 = (s.a - side.a).dot(dir), t1 = (s.b - side.a).dot(dir);
    if (t0 > t1) std::swap(t0, t1);
    spans.emplace_back(std::clamp(t0, 0.0, length), std::clamp(t1, 0.0, length));
  }
  std::sort(spans.begin(), spans.end());
  double covered = 0.0, reach = 0.0;
  for (const auto& [a, b] : spans) {
    const double from = std::max(a, reach);
    if (b > from) covered += b - from;
    reach = std::max(reach, b);
  }
  return covered;
}

void add_noise(cv::Mat* image, double sigma, unsigned seed) {
  cv::Mat noise(image->size(), CV_16SC1);
  cv::RNG rng(seed);
  rng.fill(noise, cv::RNG::NORMAL, 0.0, sigma);
  cv::Mat sum;
  image->convertTo(sum, CV_16SC1);
  sum += noise;
  sum.convertTo(*image, CV_8UC1);  // saturates
}

// A random convex polygon (3 to 6 vertices on a jittered circle) inside `cell`.
Polygon random_polygon(const cv::Rect& cell, std::mt19937* rng) {
  std::uniform_int_distribution<int> vertices(3, 6);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int n = vertices(*rng);
  const Point centre(cell.x + cell.width / 2.0, cell.y + cell.height / 2.0);
  const double radius = 0.4 * std::min(cell.width, cell.height) * (0.7 + 0.3 * unit(*rng));
  const double phase = 2.0 * M_PI * unit(*rng);
  Polygon polygon;
  for (int k = 0; k < n; ++k) {
    const double t = phase + 2.0 * M_PI * (k + 0.3 * (unit(*rng) - 0.5)) / n;
    polygon.push_back(centre + Point(std::cos(t), std::sin(t)) * radius);
  }
  return polygon;
}

void fill(cv::Mat* image, const Polygon& polygon, int level) {
  constexpr int kShift = 4;
  std::vector<cv::Point> points;
  for (const Point& p : polygon) {
    points.emplace_back(static_cast<int>(std::lround(p.x * 16)),
                        static_cast<int>(std::lround(p.y * 16)));
  }
  cv::fillPoly(*image, std::vector<std::vector<cv::Point>>{points}, cv::Scalar(level), cv::LINE_AA,
               kShift);
}

// A 640x480 image of 2x2 cells, each with one random polygon at a random level far from the
// background's, plus noise.
struct Scene {
  cv::Mat image;
  std::vector<Polygon> polygons;
};

Scene random_scene(unsigned seed, double noise = 3.0) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> level(0, 255);
  Scene scene;
  const int background = level(rng);
  scene.image = cv::Mat(480, 640, CV_8UC1, cv::Scalar(background));
  for (int cell = 0; cell < 4; ++cell) {
    const cv::Rect rect((cell % 2) * 320, (cell / 2) * 240, 320, 240);
    int foreground = level(rng);
    while (std::abs(foreground - background) < 60) foreground = level(rng);
    scene.polygons.push_back(random_polygon(rect, &rng));
    fill(&scene.image, scene.polygons.back(), foreground);
  }
  add_noise(&scene.image, noise, seed);
  return scene;
}

std::vector<Segment> run(const cv::Mat& gray, cv::Point offset = {0, 0}, cv::Size full = {},
                         const cv::Mat& band = cv::Mat()) {
  EdLines edlines;
  std::vector<Segment> segments;
  edlines.detect(gray, offset, full.empty() ? gray.size() : full, band, &segments);
  return segments;
}

// Every polygon side longer than 30 px is covered over most of its length by segments lying
// within 2 px of it and parallel to it within 2.5 degrees (corner pixels pull a fit a little).
TEST(EdLines, FindsEveryLongStraightEdge) {
  for (unsigned seed = 0; seed < 40; ++seed) {
    const Scene scene = random_scene(seed);
    const std::vector<Segment> segments = run(scene.image);
    for (const Polygon& polygon : scene.polygons) {
      for (size_t k = 0; k < polygon.size(); ++k) {
        // The anti-aliased edge of the fill lies half a pixel off the vertices' line at worst.
        const Segment side{polygon[k], polygon[(k + 1) % polygon.size()]};
        if (side.length() < 30.0) continue;
        const double covered = covered_length(side, segments, 2.0, 2.5);
        EXPECT_GT(covered, side.length() - 16.0)  // up to 8 px lost at each corner
            << "seed " << seed << " side " << side.a << "-" << side.b << " length "
            << side.length();
      }
    }
  }
}

// Segments lie on the true edges: each is within 2 px of some polygon side along its length.
TEST(EdLines, SegmentsLieOnTrueEdges) {
  for (unsigned seed = 100; seed < 130; ++seed) {
    const Scene scene = random_scene(seed);
    for (const Segment& s : run(scene.image)) {
      double best = 1e9;
      for (const Polygon& polygon : scene.polygons) {
        for (size_t k = 0; k < polygon.size(); ++k) {
          const Point a = polygon[k], b = polygon[(k + 1) % polygon.size()];
          best = std::min(best,
                          std::max({distance_to_segment(s.a, a, b), distance_to_segment(s.b, a, b),
                                    distance_to_segment(s.midpoint(), a, b)}));
        }
      }
      EXPECT_LT(best, 2.0) << "seed " << seed << " segment " << s.a << "-" << s.b;
    }
  }
}

TEST(EdLines, NothingOnFlatNoise) {
  for (unsigned seed = 0; seed < 20; ++seed) {
    std::mt19937 rng(seed);
    cv::Mat image(240 + 13 * seed, 320 + 7 * seed, CV_8UC1,
                  cv::Scalar(std::uniform_int_distribution<int>(20, 235)(rng)));
    add_noise(&image, 2.0 + 0.3 * seed, seed);  // up to 7.7 grey levels
    EXPECT_TRUE(run(image).empty()) << "seed " << seed;
  }
}

// A window around one cell's polygon gives, in whole-image coordinates, the segments the whole
// image gives there.
TEST(EdLines, WindowMatchesWholeImageInside) {
  for (unsigned seed = 200; seed < 220; ++seed) {
    const Scene scene = random_scene(seed);
    const std::vector<Segment> whole = run(scene.image);
    const int cell = static_cast<int>(seed % 4);
    const cv::Rect window = detection_roi(scene.polygons[cell], 10.0, scene.image.size());
    const std::vector<Segment> part =
        run(scene.image(window), window.tl(), scene.image.size());  // a non-contiguous view
    const cv::Rect2d inner(window.x + 5, window.y + 5, window.width - 10, window.height - 10);
    int compared = 0;
    for (const Segment& s : whole) {
      if (!inner.contains(s.a) || !inner.contains(s.b)) continue;
      ++compared;
      // The same up to rounding: coordinates differ in the last bits with the origin, which can
      // move a pixel at exactly the fit tolerance in or out of a line.
      const bool found = std::any_of(part.begin(), part.end(), [&](const Segment& t) {
        return cv::norm(s.a - t.a) < 0.05 && cv::norm(s.b - t.b) < 0.05;
      });
      EXPECT_TRUE(found) << "seed " << seed << " segment " << s.a << "-" << s.b;
    }
    EXPECT_GE(compared, 3) << "seed " << seed;
    for (const Segment& t : part) {
      EXPECT_TRUE(
          cv::Rect2d(window.x - 1, window.y - 1, window.width + 2, window.height + 2).contains(t.a))
          << t.a;
    }
  }
}

// A random scene with clutter (random strokes anywhere, some crossing the band), one of its
// polygons as the boundary, the tracker's window around it and the band mask of `radius`.
struct BandCase {
  Scene scene;
  Polygon boundary;
  cv::Rect window;
  cv::Mat crop, band;
};

BandCase band_case(unsigned seed, double radius) {
  BandCase c;
  c.scene = random_scene(seed);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> x(0, 639), y(0, 479), level(0, 255);
  for (int k = 0; k < 12; ++k) {
    cv::line(c.scene.image, {x(rng), y(rng)}, {x(rng), y(rng)}, cv::Scalar(level(rng)), 3);
  }
  c.boundary = c.scene.polygons[seed % 4];
  c.window = detection_roi(c.boundary, radius, c.scene.image.size());
  c.crop = c.scene.image(c.window).clone();
  draw_band_mask(c.boundary, c.window.tl(), radius, c.crop.size(), &c.band);
  return c;
}

// The band keeps only segments near the boundary and finds what the unbanded run finds well
// inside it.
TEST(EdLines, BandKeepsSegmentsNearBoundary) {
  const double radius = 28.0;
  int compared = 0, found_count = 0;
  for (unsigned seed = 300; seed < 330; ++seed) {
    const auto& [scene, boundary, window, crop, band] = band_case(seed, radius);
    const std::vector<Segment> banded = run(crop, window.tl(), scene.image.size(), band);
    const std::vector<Segment> unbanded = run(crop, window.tl(), scene.image.size());
    for (const Segment& s : banded) {
      for (const Point& p : {s.a, s.b, s.midpoint()}) {
        // The band's rasterised edge, plus a line end's projection from its last pixel.
        EXPECT_LE(distance_to_boundary(p, boundary), radius + 2.5) << "seed " << seed << " " << p;
      }
    }
    for (const Segment& s : unbanded) {
      if (std::max({distance_to_boundary(s.a, boundary), distance_to_boundary(s.b, boundary),
                    distance_to_boundary(s.midpoint(), boundary)}) > radius - 6.0 ||
          s.length() < 15.0) {
        continue;
      }
      // A short segment may belong to an edge that leaves the band and be split differently
      // without the part outside; long ones must all be there.
      const bool found = covered_length(s, banded, 1.5, 3.0) > 0.8 * s.length();
      ++compared;
      found_count += found ? 1 : 0;
      if (s.length() >= 30.0) {
        EXPECT_TRUE(found) << "seed " << seed << " segment " << s.a << "-" << s.b;
      }
    }
  }
  EXPECT_GE(compared, 100);
  EXPECT_GE(found_count, 0.95 * compared) << found_count << " of " << compared;
}

// With a band, only pixels near it are read (gradients are computed on the band grown by one
// pixel; smoothing, the line fit and the NFA test reach a few pixels further): replacing
// everything farther than radius + 5 px by noise changes nothing, and a detector reused after
// other windows (stale buffers outside the band) gives what a fresh one gives.
TEST(EdLines, BandedDetectionReadsOnlyPixelsNearTheBand) {
  const double radius = 28.0;
  EdLines reused;
  int segments_seen = 0;
  for (unsigned seed = 500; seed < 520; ++seed) {
    const auto& [scene, boundary, window, crop, band] = band_case(seed, radius);
    cv::Mat near;
    draw_band_mask(boundary, window.tl(), radius + 5.0, crop.size(), &near);
    const std::vector<Segment> expected = run(crop, window.tl(), scene.image.size(), band);
    segments_seen += static_cast<int>(expected.size());

    cv::Mat noisy(crop.size(), CV_8UC1);
    cv::randu(noisy, 0, 256);
    crop.copyTo(noisy, near);
    const std::vector<Segment> far_noise = run(noisy, window.tl(), scene.image.size(), band);

    // The reused detector first sees another scene's whole frame, so its buffers hold values
    // everywhere.
    std::vector<Segment> after_other;
    const Scene other = random_scene(seed + 77);
    reused.detect(other.image, {0, 0}, other.image.size(), cv::Mat(), &after_other);
    reused.detect(crop, window.tl(), scene.image.size(), band, &after_other);

    for (const std::vector<Segment>* got :
         {&far_noise, static_cast<const std::vector<Segment>*>(&after_other)}) {
      ASSERT_EQ(got->size(), expected.size()) << "seed " << seed;
      for (size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ((*got)[i].a, expected[i].a) << "seed " << seed;
        EXPECT_EQ((*got)[i].b, expected[i].b) << "seed " << seed;
      }
    }
  }
  EXPECT_GT(segments_seen, 100);
}

// Smoothing and gradients computed only near the band give the segments of the whole window's,
// through windows of changing sizes (the detector's buffers then hold other windows' values).
TEST(EdLines, ComputingNearTheBandOnlyChangesNothing) {
  EdLinesParams everywhere;
  everywhere.compute_near_band_only = false;
  EdLines near_only, whole(everywhere);
  RowSpans spans;
  int segments_seen = 0;
  for (unsigned seed = 600; seed < 640; ++seed) {
    const double radius = 8.0 + (seed % 5) * 6.0;
    const auto& [scene, boundary, window, crop, band] = band_case(seed, radius);
    band_spans(boundary, window.tl(), radius, crop.size(), &spans);
    std::vector<Segment> expected, got, from_mask;
    whole.detect(crop, window.tl(), scene.image.size(), &spans, &expected);
    near_only.detect(crop, window.tl(), scene.image.size(), &spans, &got);
    near_only.detect(crop, window.tl(), scene.image.size(), band, &from_mask);
    segments_seen += static_cast<int>(expected.size());
    for (const std::vector<Segment>* result : {&got, &from_mask}) {
      ASSERT_EQ(result->size(), expected.size()) << "seed " << seed;
      for (size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ((*result)[i].a, expected[i].a) << "seed " << seed;
        EXPECT_EQ((*result)[i].b, expected[i].b) << "seed " << seed;
      }
    }
  }
  EXPECT_GT(segments_seen, 200);
}

TEST(EdLines, Deterministic) {
  for (unsigned seed = 400; seed < 405; ++seed) {
    const Scene scene = random_scene(seed, 6.0);
    EdLines shared;
    std::vector<Segment> first, again;
    shared.detect(scene.image, {0, 0}, scene.image.size(), cv::Mat(), &first);
    const Scene other = random_scene(seed + 1000);  // something else in between
    shared.detect(other.image, {0, 0}, other.image.size(), cv::Mat(), &again);
    shared.detect(scene.image, {0, 0}, scene.image.size(), cv::Mat(), &again);
    const std::vector<Segment> fresh = run(scene.image);
    ASSERT_EQ(first.size(), again.size());
    ASSERT_EQ(first.size(), fresh.size());
    for (size_t i = 0; i < first.size(); ++i) {
      EXPECT_EQ(first[i].a, again[i].a);
      EXPECT_EQ(first[i].b, again[i].b);
      EXPECT_EQ(first[i].a, fresh[i].a);
      EXPECT_EQ(first[i].b, fresh[i].b);
    }
  }
}

void expect_inside(const std::vector<Segment>& segments, cv::Size size, const char* what) {
  for (const Segment& s : segments) {
    for (const Point& p : {s.a, s.b}) {
      EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y)) << what;
      EXPECT_TRUE(p.x >= -1.0 && p.y >= -1.0 && p.x <= size.width && p.y <= size.height)
          << what << ": " << p;
    }
  }
}

TEST(EdLines, OddImagesDoNotCrash) {
  EdLines edlines;
  std::vector<Segment> out;
  for (const cv::Size size :
       {cv::Size(0, 0), cv::Size(1, 1), cv::Size(1, 100), cv::Size(100, 1), cv::Size(2, 2),
        cv::Size(4, 4), cv::Size(5, 5), cv::Size(6, 9), cv::Size(3, 300)}) {
    cv::Mat image(size, CV_8UC1);
    if (!image.empty()) cv::randu(image, 0, 256);
    edlines.detect(image, {0, 0}, size, cv::Mat(), &out);
    expect_inside(out, size, "tiny");
  }
  const cv::Mat constant(200, 300, CV_8UC1, cv::Scalar(77));
  edlines.detect(constant, {0, 0}, constant.size(), cv::Mat(), &out);
  EXPECT_TRUE(out.empty());
  for (int cell : {1, 2, 3, 8}) {  // checkerboards: edges everywhere
    cv::Mat board(240, 320, CV_8UC1);
    for (int r = 0; r < board.rows; ++r) {
      for (int c = 0; c < board.cols; ++c) {
        board.at<std::uint8_t>(r, c) = ((r / cell + c / cell) % 2) ? 255 : 0;
      }
    }
    edlines.detect(board, {0, 0}, board.size(), cv::Mat(), &out);
    expect_inside(out, board.size(), "checkerboard");
  }
  {  // random full-contrast noise
    cv::Mat noise(480, 640, CV_8UC1);
    cv::RNG rng(3);
    rng.fill(noise, cv::RNG::UNIFORM, 0, 256);
    edlines.detect(noise, {0, 0}, noise.size(), cv::Mat(), &out);
    expect_inside(out, noise.size(), "noise");
  }
  {  // a serpentine stroke: one edge far longer than (w + h) * 8 px (OpenCV's overflow case)
    cv::Mat serpentine(480, 640, CV_8UC1, cv::Scalar(0));
    for (int r = 4; r + 4 < serpentine.rows; r += 6) {
      cv::line(serpentine, {4, r}, {635, r}, cv::Scalar(255), 2);
      const int x = (r / 6) % 2 ? 635 : 4;
      cv::line(serpentine, {x, r}, {x, r + 6}, cv::Scalar(255), 2);
    }
    edlines.detect(serpentine, {0, 0}, serpentine.size(), cv::Mat(), &out);
    expect_inside(out, serpentine.size(), "serpentine");
    EXPECT_GT(out.size(), 100u);
  }
  cv::Mat colour(50, 50, CV_8UC3, cv::Scalar(1, 2, 3));
  EXPECT_THROW(edlines.detect(colour, {0, 0}, colour.size(), cv::Mat(), &out),
               std::invalid_argument);
  cv::Mat gray(50, 50, CV_8UC1, cv::Scalar(1)), wrong_band(40, 50, CV_8UC1, cv::Scalar(255));
  EXPECT_THROW(edlines.detect(gray, {0, 0}, gray.size(), wrong_band, &out), std::invalid_argument);
}

// On the synthetic tracking scenes, most segments OpenCV's EdgeDrawing finds (20 px or longer)
// are covered by ours.
TEST(EdLines, AgreesWithOpenCvEdgeDrawing) {
  LineDetectorOptions options;
  options.kind = LineDetectorKind::kOpenCvEdLines;  // OpenCV's
  std::unique_ptr<LineDetector> opencv = make_line_detector(options);
  for (unsigned seed = 1; seed <= 12; ++seed) {
    SceneOptions scene_options;
    scene_options.seed = seed;
    scene_options.shape = static_cast<SceneShape>(seed % 3);
    const SceneFrame frame = render_frame(scene_options, Pose{}, 0);
    cv::Mat gray;
    cv::cvtColor(frame.image, gray, cv::COLOR_BGR2GRAY);
    const std::vector<Segment> theirs = opencv->detect(gray);
    const std::vector<Segment> ours = run(gray);
    int long_ones = 0, matched = 0;
    for (const Segment& s : theirs) {
      if (s.length() < 20.0) continue;
      ++long_ones;
      if (covered_length(s, ours, 1.5, 3.0) > 0.8 * s.length()) ++matched;
    }
    ASSERT_GT(long_ones, 10) << "seed " << seed;
    EXPECT_GE(matched, 0.9 * long_ones)
        << "seed " << seed << ": " << matched << " of " << long_ones;
  }
}

TEST(EdLines, MinLineLength) {
  EdLinesParams params;
  EXPECT_EQ(edlines_min_line_length(params, {640, 480}), 9);         // automatic 6, floor 9
  EXPECT_EQ(edlines_min_line_length(params, {100000, 100000}), 11);  // round(20 / 0.903 / 2)
  params.min_line_length = 4;
  EXPECT_EQ(edlines_min_line_length(params, {640, 480}), 4);
}

// The mask is set exactly on the pixels whose centres lie within the radius of the boundary
// (pixels within 1e-6 of the radius, where rounding decides, are not checked).
TEST(DrawBandMask, SetsExactlyThePixelsWithinRadius) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 30; ++trial) {
    const Polygon boundary = random_polygon(cv::Rect(0, 0, 640, 480), &rng);
    const double radius = 5.0 + 30.0 * unit(rng);
    const cv::Point offset(static_cast<int>(100 * unit(rng)), static_cast<int>(100 * unit(rng)));
    cv::Mat mask;
    draw_band_mask(boundary, offset, radius, {400, 300}, &mask);
    ASSERT_EQ(mask.type(), CV_8UC1);
    ASSERT_EQ(mask.size(), cv::Size(400, 300));
    int wrong = 0, set = 0;
    for (int r = 0; r < mask.rows; ++r) {
      for (int c = 0; c < mask.cols; ++c) {
        const double d = distance_to_boundary(Point(c + offset.x, r + offset.y), boundary);
        const bool on = mask.at<std::uint8_t>(r, c) == 255;
        set += on ? 1 : 0;
        if (std::abs(d - radius) > 1e-6 && on != (d <= radius)) ++wrong;
        if (!on) {
          EXPECT_EQ(mask.at<std::uint8_t>(r, c), 0);
        }
      }
    }
    EXPECT_EQ(wrong, 0) << "trial " << trial << " radius " << radius;
    EXPECT_GT(set, 0);
  }
  // A single point is a disc; a zero radius keeps the pixels the polyline passes through.
  cv::Mat disc;
  draw_band_mask({Point(10, 10)}, {0, 0}, 3.0, {21, 21}, &disc);
  EXPECT_EQ(cv::countNonZero(disc), 29);  // lattice points within distance 3 of a lattice point
  draw_band_mask({Point(2, 5), Point(12, 5)}, {0, 0}, 0.0, {21, 21}, &disc);
  EXPECT_EQ(cv::countNonZero(disc), 11);
  cv::Mat mask;
  draw_band_mask({Point(1e300, -1e300), Point(5, 5)}, {0, 0}, 3.0, {20, 20}, &mask);  // no crash
  draw_band_mask({}, {0, 0}, 3.0, {20, 20}, &mask);
  EXPECT_EQ(cv::countNonZero(mask), 0);
}

}  // namespace
}  // namespace scbt
