#include "scbt/synthetic/scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <random>
#include <stdexcept>

namespace scbt {
namespace {

const SceneShape kShapes[] = {SceneShape::kRim, SceneShape::kBox, SceneShape::kPolygon};

Pose random_pose(std::mt19937& rng) {
  std::uniform_real_distribution<double> x(200.0, 440.0), y(170.0, 310.0), angle(-3.2, 3.2),
      scale(0.6, 1.3);
  Pose pose;
  pose.translation = {x(rng), y(rng)};
  pose.rotation = angle(rng);
  pose.scale = scale(rng);
  return pose;
}

bool same_image(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && cv::norm(a, b, cv::NORM_INF) == 0.0;
}

TEST(SceneTest, SameSeedRendersIdenticalFrames) {
  for (SceneShape shape : kShapes) {
    for (std::uint32_t seed = 1; seed <= 4; ++seed) {
      SceneOptions options;
      options.seed = seed;
      options.shape = shape;
      const std::vector<Pose> poses = smooth_motion_path({}, 3);
      const std::vector<SceneFrame> a = render_clip(options, poses);
      const std::vector<SceneFrame> b = render_clip(options, poses);
      ASSERT_EQ(a.size(), 3u);
      for (size_t i = 0; i < a.size(); ++i) {
        EXPECT_TRUE(same_image(a[i].image, b[i].image)) << "seed " << seed << " frame " << i;
        EXPECT_EQ(a[i].truth, b[i].truth);
        EXPECT_EQ(a[i].image.type(), CV_8UC3);
        EXPECT_EQ(a[i].image.size(), options.size);
      }
      // Noise differs from frame to frame, so a static pose still gives distinct frames.
      const std::vector<SceneFrame> still = render_clip(options, {Pose(), Pose()});
      EXPECT_FALSE(same_image(still[0].image, still[1].image));
    }
  }
}

TEST(SceneTest, DifferentSeedsRenderDifferentBackgrounds) {
  SceneOptions a;
  SceneOptions b;
  b.seed = a.seed + 1;
  a.noise_sigma = b.noise_sigma = 0.0;
  const cv::Rect2d region(250, 200, 140, 80);
  const cv::Mat background_a = render_background(a, region);
  const cv::Mat background_b = render_background(b, region);
  EXPECT_FALSE(same_image(background_a, background_b));
  // Clutter actually shows: the background is far from flat.
  cv::Scalar mean, stddev;
  cv::meanStdDev(background_a, mean, stddev);
  EXPECT_GT(stddev[0], 8.0);
}

TEST(SceneTest, TrueAreaIsInvariantUnderTranslationAndRotation) {
  for (std::uint32_t seed = 1; seed <= 20; ++seed) {
    std::mt19937 rng(seed);
    for (SceneShape shape : kShapes) {
      SceneOptions options;
      options.seed = seed;
      options.shape = shape;
      const Polygon model = object_model(options);
      ASSERT_GE(model.size(), 4u);
      EXPECT_TRUE(is_simple(model)) << to_string(shape) << " seed " << seed;
      const double model_area = area(model);
      ASSERT_GT(model_area, 0.0);
      Pose pose = random_pose(rng);
      pose.scale = 1.0;
      const SceneFrame frame = render_frame(options, pose, 0);
      EXPECT_NEAR(area(frame.truth), model_area, 1e-9 * model_area);
      EXPECT_TRUE(is_simple(frame.truth));
      // ... and scales with the square of the scale.
      pose.scale = 0.75;
      EXPECT_NEAR(area(apply_pose(pose, model)), 0.5625 * model_area, 1e-9 * model_area);
      // The centroid follows the translation (the model is centred near the origin).
      pose.scale = 1.0;
      const Point moved = centroid(apply_pose(pose, model)) - apply_pose(pose, centroid(model));
      EXPECT_NEAR(moved.x, 0.0, 1e-9);
      EXPECT_NEAR(moved.y, 0.0, 1e-9);
    }
  }
}

TEST(SceneTest, ObjectIsFlatAndEdgesLandOnTheTruthToSubPixelAccuracy) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> fraction(0.0, 1.0);
  for (int trial = 0; trial < 10; ++trial) {
    SceneOptions options;
    options.seed = 100 + trial;
    options.shape = SceneShape::kBox;
    options.noise_sigma = 0.0;
    options.blur_sigma = 0.0;
    options.clutter_strokes = 0;  // smooth shading only, so the background is known exactly
    Pose pose;
    pose.translation = {300.0 + 20 * fraction(rng), 230.0 + 20 * fraction(rng)};
    const Polygon model = object_model(options);
    const cv::Mat background = render_background(options, cv::Rect2d(200, 150, 240, 180));
    const SceneFrame frame = render_frame(options, background, model, pose, 0);
    cv::Mat grey;
    cv::cvtColor(frame.image, grey, cv::COLOR_BGR2GRAY);

    // Pixels well inside are exactly the object's level; well outside, the background.
    std::vector<cv::Point2f> contour;
    for (const Point& p : frame.truth) contour.emplace_back(p);
    for (int y = 100; y < 380; y += 3) {
      for (int x = 150; x < 490; x += 3) {
        const double d = cv::pointPolygonTest(contour, cv::Point2f(x, y), true);
        if (d > 1.0) {
          ASSERT_EQ(grey.at<uchar>(y, x), options.object_level) << x << "," << y;
        } else if (d < -1.0) {
          ASSERT_EQ(grey.at<uchar>(y, x), background.at<uchar>(y, x)) << x << "," << y;
        }
      }
    }
    // The box's top edge is horizontal at rotation 0: down a column through it, the summed
    // coverage equals the covered length, locating the edge to a small fraction of a pixel.
    const double top = frame.truth[0].y;
    const int column = cvRound(pose.translation.x);
    const int first = cvFloor(top) - 3;
    const int last = cvFloor(top) + 4;
    double covered = 0.0;
    for (int y = first; y <= last; ++y) {
      const double bg = background.at<uchar>(y, column);
      covered += (grey.at<uchar>(y, column) - bg) / (options.object_level - bg);
    }
    const double expected = (last + 0.5) - top;
    EXPECT_NEAR(covered, expected, 0.05) << "top edge at y = " << top;
  }
}

TEST(SceneTest, SmoothPathStartsAtTheStartPoseAndMovesGently) {
  for (SceneShape shape : kShapes) {
    SceneOptions options;
    options.shape = shape;
    const Polygon model = object_model(options);
    MotionOptions motion;
    motion.start.translation = {310.0, 250.0};
    motion.start.rotation = 0.2;
    const std::vector<Pose> poses = smooth_motion_path(motion, 150);
    ASSERT_EQ(poses.size(), 150u);
    EXPECT_EQ(poses[0].translation, motion.start.translation);
    EXPECT_DOUBLE_EQ(poses[0].rotation, motion.start.rotation);
    EXPECT_DOUBLE_EQ(poses[0].scale, motion.start.scale);
    Polygon previous = apply_pose(poses[0], model);
    double largest_step = 0.0;
    for (const Pose& pose : poses) {
      const Polygon current = apply_pose(pose, model);
      const cv::Rect2d box = bounding_box(current);
      EXPECT_GE(box.x, 0.0);
      EXPECT_GE(box.y, 0.0);
      EXPECT_LE(box.x + box.width, options.size.width);
      EXPECT_LE(box.y + box.height, options.size.height);
      for (size_t i = 0; i < current.size(); ++i) {
        largest_step = std::max(largest_step, cv::norm(current[i] - previous[i]));
      }
      previous = current;
    }
    // Well within the tracker's 20 px filter distance, but not standing still.
    EXPECT_LT(largest_step, 10.0) << to_string(shape);
    EXPECT_GT(largest_step, 2.0) << to_string(shape);
  }
}

TEST(SceneTest, LinearPathShiftsByTheGivenStep) {
  Pose start;
  start.rotation = 0.3;
  start.scale = 0.9;
  const std::vector<Pose> poses = linear_motion_path(start, {1.5, -0.5}, 20);
  ASSERT_EQ(poses.size(), 20u);
  for (size_t k = 0; k < poses.size(); ++k) {
    EXPECT_NEAR(poses[k].translation.x, start.translation.x + 1.5 * k, 1e-9);
    EXPECT_NEAR(poses[k].translation.y, start.translation.y - 0.5 * k, 1e-9);
    EXPECT_EQ(poses[k].rotation, start.rotation);
    EXPECT_EQ(poses[k].scale, start.scale);
  }
}

TEST(SceneTest, MeanBoundaryDistanceOfAShiftedSquareMatchesTheClosedForm) {
  // Square of side L shifted sideways by d, one way: the trailing vertical side is d away (L d),
  // the leading one d away except within d of the corners (L d - d^2), and each horizontal side
  // has an uncovered end of length d contributing d^2/2. Total 2 L d over a perimeter of 4 L.
  const double side = 100.0;
  const Polygon square = {{0, 0}, {side, 0}, {side, side}, {0, side}};
  for (double d : {0.5, 1.0, 2.0, 4.0, 8.0}) {
    Polygon shifted = square;
    for (Point& p : shifted) p.x += d;
    const double expected = d / 2;
    EXPECT_NEAR(mean_boundary_distance(square, shifted, 0.25), expected, 0.01) << d;
    EXPECT_NEAR(mean_boundary_distance(shifted, square, 0.25), expected, 0.01) << d;
  }
  EXPECT_DOUBLE_EQ(mean_boundary_distance(square, square), 0.0);
  EXPECT_TRUE(std::isinf(mean_boundary_distance(square, {{1, 1}})));
}

TEST(SceneTest, SampleBoundaryKeepsVerticesAndSpacing) {
  const Polygon triangle = {{0, 0}, {10, 0}, {0, 7}};
  const std::vector<Point> samples = sample_boundary(triangle, 0.9);
  ASSERT_FALSE(samples.empty());
  EXPECT_EQ(samples.front(), triangle[0]);
  for (size_t i = 0; i < samples.size(); ++i) {
    const Point next = samples[(i + 1) % samples.size()];
    EXPECT_LE(cv::norm(next - samples[i]), 0.9 + 1e-9);
    EXPECT_LT(distance_to_boundary(samples[i], triangle), 1e-9);
  }
  EXPECT_THROW(sample_boundary(triangle, 0.0), std::invalid_argument);
}

TEST(SceneTest, OptionsAreChecked) {
  EXPECT_NO_THROW(SceneOptions().check());
  SceneOptions bad;
  bad.noise_sigma = -1.0;
  EXPECT_THROW(bad.check(), std::invalid_argument);
  bad = SceneOptions();
  bad.size = {10, 10};
  EXPECT_THROW(bad.check(), std::invalid_argument);
  bad = SceneOptions();
  bad.object_size = 1000.0;
  EXPECT_THROW(bad.check(), std::invalid_argument);
  bad = SceneOptions();
  bad.near_share = 1.5;
  EXPECT_THROW(bad.check(), std::invalid_argument);
  MotionOptions motion;
  motion.period = 0;
  EXPECT_THROW(motion.check(), std::invalid_argument);
  EXPECT_EQ(parse_scene_shape("box"), SceneShape::kBox);
  EXPECT_EQ(parse_scene_shape(to_string(SceneShape::kRim)), SceneShape::kRim);
  EXPECT_THROW(parse_scene_shape("cup"), std::invalid_argument);
}

}  // namespace
}  // namespace scbt
