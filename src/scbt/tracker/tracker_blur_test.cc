// EdgeBlurOptions on rendered views: in a blurred, low-contrast view the hexagon's edge falls
// below EDLines' published thresholds; scaled for the blur measured across the tracked boundary
// they detect it again (with no weak-frame retry to help), and a sharp view is tracked exactly
// as without the scaling.
#include <gtest/gtest.h>

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <string>

#include "scbt/testing/hexagon_pan_test_util.h"

namespace scbt {
namespace {

// The 640x480 view at `corner` with its contrast scaled by `contrast` about mid-grey and
// Gaussian-blurred by `blur` px (none for 0).
cv::Mat blurred_view(const cv::Mat& scene, cv::Point corner, double contrast, double blur) {
  cv::Mat view;
  scene(cv::Rect(corner, cv::Size(640, 480)))
      .convertTo(view, CV_8U, contrast, 128.0 * (1.0 - contrast));
  if (blur > 0.0) cv::GaussianBlur(view, view, cv::Size(0, 0), blur);
  return view;
}

// The blur's scaling on or off, and neither the exposure's scaling nor the weak-frame retry,
// which lower the thresholds on their own.
TrackerOptions blur_options(bool adapt) {
  TrackerOptions options;
  options.blur.adapt = adapt;
  options.exposure.normalize = false;
  options.adaptive_thresholds.retry_weak_frames = false;
  return options;
}

PanRun track_pan(double contrast, double blur, bool adapt, unsigned seed) {
  const cv::Mat scene = render_hexagon_scene(seed);
  return track_pan(blur_options(adapt),
                   [&](cv::Point corner) { return blurred_view(scene, corner, contrast, blur); });
}

std::string describe(unsigned seed, const PanRun& scaled, const PanRun& published) {
  std::ostringstream where;
  where << "seed " << seed << ": scaled worst " << scaled.max_error << " px, held " << scaled.held
        << "; published worst " << published.max_error << " px, held " << published.held;
  return where.str();
}

TEST(TrackerBlurTest, BlurredViewIsFollowedWithThresholdsScaledToItsBlur) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const PanRun scaled = track_pan(0.25, 3.5, true, seed);
    const PanRun published = track_pan(0.25, 3.5, false, seed);
    const std::string where = describe(seed, scaled, published);
    EXPECT_LT(scaled.max_error, 2.0) << where;
    EXPECT_EQ(scaled.held, 0) << where;
    EXPECT_GT(published.held, kPanFrames / 2) << where;
  }
}

TEST(TrackerBlurTest, BlurSettingInIsMeasuredAndFollowed) {
  // Sharp at first; then a blur growing by 0.35 px a frame to 3.5 px at full contrast, which
  // the published thresholds lose on the way; then dim as well, which only the scaled thresholds
  // find (the test above). The spread must be followed as it grows.
  constexpr int kSharpFrames = 4, kDimFrom = 14;
  for (unsigned seed : {1u, 2u}) {
    const cv::Mat scene = render_hexagon_scene(seed);
    const auto view = [&](cv::Point corner) {
      const int k = (corner.x - kPanStart.x) / kPanStep.x;
      if (k < kSharpFrames) return blurred_view(scene, corner, 1.0, 0.0);
      const double blur = std::min(3.5, 0.35 * (k - kSharpFrames + 1));
      return blurred_view(scene, corner, k < kDimFrom ? 1.0 : 0.25, blur);
    };
    const PanRun scaled = track_pan(blur_options(true), view);
    const PanRun published = track_pan(blur_options(false), view);
    const std::string where = describe(seed, scaled, published);
    EXPECT_LT(scaled.max_error, 2.0) << where;
    EXPECT_EQ(scaled.held, 0) << where;
    EXPECT_GE(published.held, kPanFrames - kDimFrom - 1) << where;
  }
}

TEST(TrackerBlurTest, SharpViewIsTrackedExactlyAsWithoutScaling) {
  const PanRun scaled = track_pan(1.0, 0.0, true, 4);
  const PanRun published = track_pan(1.0, 0.0, false, 4);
  ASSERT_EQ(scaled.tracked.size(), published.tracked.size());
  for (size_t k = 0; k < scaled.tracked.size(); ++k) {
    EXPECT_EQ(scaled.tracked[k], published.tracked[k]) << "frame " << k + 1;
  }
  EXPECT_LT(scaled.max_error, 1.5);
}

}  // namespace
}  // namespace scbt
