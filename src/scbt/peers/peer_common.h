// Small pieces shared by the peer trackers (the init checks are tracker/frame_checks.h): warping a
// polygon by a homography, the numeric blow-up guard, and a stopwatch.
#pragma once

#include <chrono>
#include <opencv2/core/mat.hpp>

#include "scbt/geometry/polygon.h"
#include "scbt/tracker/frame_checks.h"

namespace scbt {

// Maps every vertex through the 3x3 homography `h` (CV_64F). Vertices mapped to infinity come
// out non-finite, which plausible_update rejects.
Polygon apply_homography(const cv::Mat& h, const Polygon& polygon);

// The blow-up guard of every peer: true when `candidate` has finite coordinates, is simple, its
// area is within a factor `max_area_factor` of `reference_area`, and its centroid stays within
// the frame grown by half its size on every side.
bool plausible_update(const Polygon& candidate, double reference_area, const cv::Size& frame_size,
                      double max_area_factor = 4.0);

class Stopwatch {
 public:
  Stopwatch() : start_(std::chrono::steady_clock::now()) {}
  double elapsed_ms() const {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_)
        .count();
  }

 private:
  std::chrono::steady_clock::time_point start_;
};

}  // namespace scbt
