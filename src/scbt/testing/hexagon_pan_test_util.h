// Shared by the tests that degrade a camera's view (dim, blurred): the camera pans over the
// rendered hexagon scene (hexagon_scene_test_util.h) and the hexagon is tracked from its outline.
#pragma once

#include <algorithm>
#include <functional>
#include <opencv2/core.hpp>
#include <vector>

#include "scbt/synthetic/scene.h"
#include "scbt/testing/hexagon_scene_test_util.h"
#include "scbt/tracker/tracker.h"

namespace scbt {

constexpr int kPanFrames = 20;
const cv::Point kPanStart(160, 120);
const cv::Point kPanStep(3, 2);  // the camera pans this far per frame

// The hexagon in the view of frame k of the pan.
inline Polygon pan_truth_at(int k) {
  const cv::Point corner = kPanStart + k * kPanStep;
  return hexagon({480.0 - corner.x, 360.0 - corner.y}, 70);
}

struct PanRun {
  double max_error = 0.0;  // px, mean_boundary_distance to the truth, worst frame
  int held = 0;
  std::vector<Polygon> tracked;
};

// Tracks the pan with `options`; `view(corner)` is the 640x480 frame at `corner` as the camera
// gives it.
inline PanRun track_pan(const TrackerOptions& options,
                        const std::function<cv::Mat(cv::Point)>& view) {
  Tracker tracker(options);
  tracker.init(view(kPanStart), pan_truth_at(0));
  PanRun run;
  for (int k = 1; k < kPanFrames; ++k) {
    const TrackResult result = tracker.track(view(kPanStart + k * kPanStep));
    run.held += result.held ? 1 : 0;
    run.max_error =
        std::max(run.max_error, mean_boundary_distance(result.boundary, pan_truth_at(k), 0.5));
    run.tracked.push_back(result.boundary);
  }
  return run;
}

}  // namespace scbt
