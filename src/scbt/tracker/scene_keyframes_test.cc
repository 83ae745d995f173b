// Registering a keyframe with a later view of the same rendered scene: the similarity is found
// (scale, rotation, translation), an unrelated or blank view gives none, and SceneKeyframes moves
// the kept boundary to where the scene put it.
#include "scbt/tracker/scene_keyframes.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "scbt/synthetic/scene.h"

namespace scbt {
namespace {

cv::Matx23d similarity(double scale, double angle, Point shift) {
  const double c = scale * std::cos(angle), s = scale * std::sin(angle);
  return {c, -s, shift.x, s, c, shift.y};
}

Point apply(const cv::Matx23d& m, const Point& p) {
  return {m(0, 0) * p.x + m(0, 1) * p.y + m(0, 2), m(1, 0) * p.x + m(1, 1) * p.y + m(1, 2)};
}

cv::Mat gray_of(const SceneFrame& frame) {
  cv::Mat gray;
  cv::cvtColor(frame.image, gray, cv::COLOR_BGR2GRAY);
  return gray;
}

cv::Mat warped(const cv::Mat& image, const cv::Matx23d& m) {
  cv::Mat out;
  cv::warpAffine(image, out, cv::Mat(m), image.size(), cv::INTER_LINEAR, cv::BORDER_REFLECT);
  return out;
}

SceneFrame scene_frame(std::uint32_t seed) {
  SceneOptions options;
  options.seed = seed;
  return render_frame(options, Pose{Point(320.0, 240.0), 0.0, 1.0});
}

class RegisterViewsTest : public ::testing::TestWithParam<std::uint32_t> {};

TEST_P(RegisterViewsTest, FindsTheSimilarityOfAMovedView) {
  const cv::Mat before = gray_of(scene_frame(GetParam()));
  for (const cv::Matx23d& truth :
       {similarity(0.6, 0.3, Point(150.0, 60.0)), similarity(1.5, -0.2, Point(-120.0, -80.0)),
        similarity(1.0, 0.0, Point(40.0, -30.0))}) {
    const std::optional<cv::Matx23d> found = register_views(before, {0, 0}, warped(before, truth));
    ASSERT_TRUE(found.has_value());
    for (const Point& p : {Point(250.0, 200.0), Point(380.0, 260.0), Point(320.0, 240.0)}) {
      EXPECT_LT(cv::norm(apply(*found, p) - apply(truth, p)), 2.0);
    }
  }
}

TEST_P(RegisterViewsTest, NoneForAnUnrelatedOrBlankView) {
  const cv::Mat before = gray_of(scene_frame(GetParam()));
  EXPECT_FALSE(register_views(before, {0, 0}, gray_of(scene_frame(GetParam() + 100))));
  EXPECT_FALSE(register_views(before, {0, 0}, cv::Mat(before.size(), CV_8U, cv::Scalar(128))));
}

INSTANTIATE_TEST_SUITE_P(Seeds, RegisterViewsTest, ::testing::Values(1u, 2u, 3u));

TEST(SceneKeyframes, MovesTheKeptBoundaryWhereTheSceneWent) {
  const SceneFrame frame = scene_frame(4);
  SceneKeyframes keyframes;
  EXPECT_FALSE(keyframes.locate(gray_of(frame)));  // nothing kept yet
  for (int k = 0; k < 12; ++k) keyframes.offer(frame.image, frame.truth);
  const cv::Matx23d view = similarity(0.6, 0.25, Point(160.0, 50.0));
  const std::optional<RegisteredBoundary> found = keyframes.locate(warped(gray_of(frame), view));
  ASSERT_TRUE(found.has_value());
  EXPECT_NEAR(found->scale, 0.6, 0.02);
  ASSERT_EQ(found->boundary.size(), frame.truth.size());
  for (size_t i = 0; i < frame.truth.size(); ++i) {
    EXPECT_LT(cv::norm(found->boundary[i] - apply(view, frame.truth[i])), 2.0) << i;
  }
  keyframes.clear();
  EXPECT_FALSE(keyframes.locate(warped(gray_of(frame), view)));
}

TEST(KeyframeOptions, CheckRejectsBadValues) {
  EXPECT_NO_THROW(KeyframeOptions().check());
  KeyframeOptions o;
  o.keep_every = 0;
  EXPECT_THROW(o.check(), std::invalid_argument);
  o = KeyframeOptions();
  o.min_inliers = 2;
  EXPECT_THROW(o.check(), std::invalid_argument);
}

}  // namespace
}  // namespace scbt
