// Drawing a tracked frame like the paper's Fig. 2: detected segments, the generated gap fillers
// among the kept ones, and the boundary.
#pragma once

#include <opencv2/core/mat.hpp>
#include <string>

#include "scbt/tracker/tracker.h"

namespace scbt {

// Returns a BGR copy of `frame` with all detected segments (thin grey), the kept detected
// segments (red), the generated segments (blue), the boundary coloured by its state (green
// tracking, amber uncertain, red lost, the latter two also named beside it) and a one-line status
// text.
cv::Mat annotate_frame(const cv::Mat& frame, const TrackDebug& debug, const TrackResult& result,
                       const std::string& status);

// The boundary's colour (BGR) in a frame of this state.
cv::Scalar state_color(TrackState state);

// Draws a closed polygon.
void draw_polygon(cv::Mat* image, const Polygon& polygon, const cv::Scalar& color, int thickness);

}  // namespace scbt
