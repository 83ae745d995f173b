// A camera that pans fast and then turns back, as a hand-held or robot camera at a low frame rate
// does: the boundary moves up to 26 px per frame (beyond the 20 px search band) and then reverses.
// Searching where the image motion around the boundary moved it follows every frame; searching
// where it was, or where its last velocity extrapolates, loses it (recovery by motion is off here
// so that only the prediction is tested). A prediction that finds nothing falls back to where the
// boundary was.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <vector>

#include "scbt/testing/hexagon_scene_test_util.h"
#include "scbt/tracker/option_table.h"
#include "scbt/tracker/tracker.h"

namespace scbt {
namespace {

double mean_vertex_distance(const Polygon& tracked, const Polygon& truth) {
  double sum = 0.0;
  for (const Point& p : tracked) sum += distance_to_boundary(p, truth);
  return sum / static_cast<double>(tracked.size());
}

enum class Prediction { kNone, kExtrapolated, kMeasured };

TrackerOptions options_for(Prediction prediction) {
  TrackerOptions options;
  options.recover_by_motion = false;
  set_tracker_option(&options, "predict_motion", prediction != Prediction::kNone);
  options.measure_motion = prediction == Prediction::kMeasured;
  return options;
}

// The largest mean vertex distance to the truth over a pan whose horizontal steps (px per frame)
// are `steps` (held frames count as where the boundary was held).
double worst_error_over_pan(const cv::Mat& scene, const TrackerOptions& options,
                            const std::vector<int>& steps) {
  Tracker tracker(options);
  const cv::Point start(160, 120);
  const Point centre(480.0 - start.x, 360.0 - start.y);
  tracker.init(scene(cv::Rect(start, cv::Size(640, 480))), hexagon(centre, 70));
  cv::Point corner = start;
  double worst = 0.0;
  for (const int step : steps) {
    corner.x += step;
    corner.y += step / 5;
    const TrackResult r = tracker.track(scene(cv::Rect(corner, cv::Size(640, 480))));
    const Point shift(corner.x - start.x, corner.y - start.y);
    worst = std::max(worst, mean_vertex_distance(r.boundary, hexagon(centre - shift, 70)));
  }
  return worst;
}

// Speeding up, then turning back.
const std::vector<int> kPanThatTurnsBack = {10, 20, 26, 26, -26, -26, -20};

double worst_error_over_pan(const cv::Mat& scene, Prediction prediction) {
  return worst_error_over_pan(scene, options_for(prediction), kPanThatTurnsBack);
}

class MotionPredictionTest : public ::testing::TestWithParam<int> {};

TEST_P(MotionPredictionTest, MeasuredImageMotionFollowsAFastPanThatTurnsBack) {
  const cv::Mat scene = render_hexagon_scene(300 + GetParam());
  EXPECT_LT(worst_error_over_pan(scene, Prediction::kMeasured), 2.0);
  // The same pan defeats the unmoved band (26 px steps) and the extrapolated velocity (which
  // overshoots by twice the step when the pan turns back).
  EXPECT_GT(worst_error_over_pan(scene, Prediction::kNone), 10.0);
  EXPECT_GT(worst_error_over_pan(scene, Prediction::kExtrapolated), 10.0);
}

// A pan that speeds up to 48 px per frame and then turns back slowly: the extrapolated velocity
// puts the search 63 px past the boundary, where nothing is found; where the boundary was, 15 px
// off, it is found.
TEST_P(MotionPredictionTest, AWrongPredictionFallsBackToWhereTheBoundaryWas) {
  const cv::Mat scene = render_hexagon_scene(300 + GetParam());
  const std::vector<int> pan_that_stops = {12, 24, 36, 48, -15, -15};
  TrackerOptions options = options_for(Prediction::kExtrapolated);
  options.confirm_motion = false;  // the contrast profile would refuse the overshoot itself
  ASSERT_TRUE(options.fall_back_unmoved);
  EXPECT_LT(worst_error_over_pan(scene, options, pan_that_stops), 2.0);
  options.fall_back_unmoved = false;
  EXPECT_GT(worst_error_over_pan(scene, options, pan_that_stops), 10.0);
}

INSTANTIATE_TEST_SUITE_P(Seeds, MotionPredictionTest, ::testing::Range(0, 3));

}  // namespace
}  // namespace scbt
