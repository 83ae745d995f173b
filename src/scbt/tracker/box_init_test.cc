// Initialisation from a box: the most salient closed boundary inside a box drawn around a
// rendered object is the object's outline.
#include "scbt/tracker/box_init.h"

#include <gtest/gtest.h>

#include <tuple>

#include "scbt/synthetic/scene.h"
#include "scbt/tracker/tracker.h"

namespace scbt {
namespace {

class BoxInitTest : public ::testing::TestWithParam<std::tuple<SceneShape, std::uint32_t>> {};

TEST_P(BoxInitTest, FindsTheObjectsOutlineInsideALooseBox) {
  const auto [shape, seed] = GetParam();
  SceneOptions scene;
  scene.shape = shape;
  scene.seed = seed;
  Pose pose;
  pose.rotation = 0.3 * seed;
  const SceneFrame frame = render_frame(scene, pose);
  // A box 15 % larger than the object on every side, as a user would draw it.
  const cv::Rect2d tight = bounding_box(frame.truth);
  const double margin = 0.15 * std::max(tight.width, tight.height);
  const cv::Rect box(cvRound(tight.x - margin), cvRound(tight.y - margin),
                     cvRound(tight.width + 2 * margin), cvRound(tight.height + 2 * margin));
  Tracker tracker;
  const Polygon found = tracker.init_from_box(frame.image, box);
  EXPECT_LT(mean_boundary_distance(found, frame.truth), 1.5) << to_string(shape) << " " << seed;
  EXPECT_EQ(tracker.boundary(), found);
}

INSTANTIATE_TEST_SUITE_P(ShapesAndSeeds, BoxInitTest,
                         ::testing::Combine(::testing::Values(SceneShape::kRim, SceneShape::kBox,
                                                              SceneShape::kPolygon),
                                            ::testing::Values(1u, 2u, 3u)),
                         [](const ::testing::TestParamInfo<BoxInitTest::ParamType>& info) {
                           return to_string(std::get<0>(info.param)) + "_seed" +
                                  std::to_string(std::get<1>(info.param));
                         });

TEST(BoxInitErrorsTest, BadBoxesAndEmptyBoxesAreReported) {
  const SceneFrame frame = render_frame(SceneOptions{}, Pose{});
  Tracker tracker;
  EXPECT_THROW(tracker.init_from_box(frame.image, cv::Rect(600, 400, 100, 100)),
               std::invalid_argument);  // leaves the frame
  EXPECT_THROW(tracker.init_from_box(frame.image, cv::Rect(10, 10, 4, 4)), std::invalid_argument);
  const cv::Mat blank(480, 640, CV_8UC3, cv::Scalar::all(128));
  EXPECT_THROW(tracker.init_from_box(blank, cv::Rect(100, 100, 200, 200)), std::runtime_error);
  EXPECT_FALSE(tracker.initialized());
}

TEST(MostSalientBoundaryTest, PrefersTheClosedSquareOverAnOpenOne) {
  // A closed square (no gap) and, far away, three sides of a larger one.
  const std::vector<Segment> segments = {
      {{0, 0}, {40, 0}},    {{40, 0}, {40, 40}},   {{40, 40}, {0, 40}},   {{0, 40}, {0, 0}},
      {{100, 0}, {160, 0}}, {{160, 0}, {160, 60}}, {{160, 60}, {100, 60}}};
  const std::optional<Polygon> best = most_salient_boundary(segments, 100.0);
  ASSERT_TRUE(best.has_value());
  EXPECT_NEAR(area(*best), 1600.0, 1e-6);
  EXPECT_FALSE(most_salient_boundary(segments, 1e6).has_value());
}

}  // namespace
}  // namespace scbt
