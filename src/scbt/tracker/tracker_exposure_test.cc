// ExposureOptions on rendered views: in a dim view the hexagon's edge falls below EDLines'
// published thresholds; with the frame's grey levels stretched to its exposure they detect it
// again (with no weak-frame retry to help), a box drawn in a dim frame finds the outline, and a
// well-exposed view is tracked exactly as without the stretch.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <sstream>
#include <stdexcept>

#include "scbt/synthetic/scene.h"
#include "scbt/testing/dim_camera_test_util.h"
#include "scbt/testing/hexagon_pan_test_util.h"

namespace scbt {
namespace {

// The 640x480 view at `corner`, as a dim camera gives it (dim_camera_frame).
cv::Mat dim_view(const cv::Mat& scene, cv::Point corner, double brightness, double noise,
                 cv::RNG* rng) {
  return dim_camera_frame(scene(cv::Rect(corner, cv::Size(640, 480))), brightness, noise, rng);
}

PanRun track_pan(double brightness, double noise, bool normalize, unsigned seed) {
  const cv::Mat scene = render_hexagon_scene(seed);
  TrackerOptions options;
  options.exposure.normalize = normalize;
  // Without the weak-frame retry, which lowers the thresholds on its own on a held frame.
  options.adaptive_thresholds.retry_weak_frames = false;
  cv::RNG rng(seed);
  return track_pan(
      options, [&](cv::Point corner) { return dim_view(scene, corner, brightness, noise, &rng); });
}

TEST(TrackerExposureTest, DimViewIsFollowedWithThresholdsScaledToItsContrast) {
  for (unsigned seed : {1u, 2u, 3u}) {
    // At 7 % of the light the hexagon's step (about 125 grey levels lit) is under 9 levels:
    // below the published gradient threshold. The frame's spread is as low.
    const PanRun scaled = track_pan(0.07, 0.5, true, seed);
    const PanRun published = track_pan(0.07, 0.5, false, seed);
    std::ostringstream where;
    where << "seed " << seed << ": scaled worst " << scaled.max_error << " px, held " << scaled.held
          << "; published worst " << published.max_error << " px, held " << published.held;
    EXPECT_LT(scaled.max_error, 1.5) << where.str();
    EXPECT_EQ(scaled.held, 0) << where.str();
    EXPECT_GT(published.held, kPanFrames / 2) << where.str();
  }
}

TEST(TrackerExposureTest, WellExposedViewIsTrackedExactlyAsWithoutScaling) {
  const PanRun scaled = track_pan(1.0, 2.0, true, 4);
  const PanRun published = track_pan(1.0, 2.0, false, 4);
  ASSERT_EQ(scaled.tracked.size(), published.tracked.size());
  for (size_t k = 0; k < scaled.tracked.size(); ++k) {
    EXPECT_EQ(scaled.tracked[k], published.tracked[k]) << "frame " << k + 1;
  }
  EXPECT_LT(scaled.max_error, 1.5);
}

// A box drawn in a dim frame: the search for the most salient boundary in it has no previous
// boundary to adapt thresholds to, only the frame's exposure.
TEST(TrackerExposureTest, BoxInADimFrameFindsTheOutline) {
  for (unsigned seed : {1u, 2u, 3u}) {
    cv::RNG rng(seed);
    const cv::Mat frame = dim_view(render_hexagon_scene(seed), kPanStart, 0.07, 0.5, &rng);
    const cv::Rect box(200, 120, 240, 240);  // the hexagon at (320, 240), radius 70
    Tracker scaled;
    EXPECT_LT(mean_boundary_distance(scaled.init_from_box(frame, box), pan_truth_at(0)), 1.5)
        << "seed " << seed;
    TrackerOptions published_only;
    published_only.exposure.normalize = false;
    Tracker published(published_only);
    EXPECT_THROW(published.init_from_box(frame, box), std::runtime_error) << "seed " << seed;
  }
}

}  // namespace
}  // namespace scbt
