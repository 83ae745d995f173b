#include "scbt/tracker/frame_checks.h"

#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

#include "scbt/geometry/polygon_io.h"

namespace scbt {

namespace {

// True when `m` is the only header on a buffer OpenCV allocated: writing into it changes no other
// Mat. A view of a caller's frame (a header over a numpy array has no UMatData at all, one over
// a cv::Mat shares its count) is not.
bool sole_owner(const cv::Mat& m) { return m.u != nullptr && m.u->refcount == 1; }

}  // namespace

void to_gray(const cv::Mat& frame, cv::Mat* gray) {
  if (frame.empty()) throw std::invalid_argument("frame is empty");
  if (frame.depth() != CV_8U) {
    throw std::invalid_argument("frame must be 8-bit, got depth " + std::to_string(frame.depth()));
  }
  if (frame.channels() != 1 && frame.channels() != 3 && frame.channels() != 4) {
    throw std::invalid_argument("frame must have 1, 3 or 4 channels, got " +
                                std::to_string(frame.channels()));
  }
  // `gray` may still be a view of an earlier caller's frame, or be shared: never write into
  // that; a new buffer instead.
  if (!sole_owner(*gray)) gray->release();
  switch (frame.channels()) {
    case 1:
      frame.copyTo(*gray);
      return;
    case 3:
      cv::cvtColor(frame, *gray, cv::COLOR_BGR2GRAY);
      return;
    default:
      cv::cvtColor(frame, *gray, cv::COLOR_BGRA2GRAY);
      return;
  }
}

void check_tracker_init(const cv::Mat& frame, const Polygon& polygon, cv::Mat* gray) {
  to_gray(frame, gray);
  check_boundary_polygon(polygon);
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Point& p = polygon[i];
    if (p.x < 0 || p.y < 0 || p.x > frame.cols || p.y > frame.rows) {
      throw std::invalid_argument("polygon vertex " + std::to_string(i + 1) + " (" +
                                  std::to_string(p.x) + ", " + std::to_string(p.y) +
                                  ") is outside the " + std::to_string(frame.cols) + "x" +
                                  std::to_string(frame.rows) + " frame");
    }
  }
}

void check_frame_size(const cv::Mat& frame, const cv::Size& expected) {
  if (frame.size() != expected) {
    throw std::invalid_argument("frame size changed from " + std::to_string(expected.width) + "x" +
                                std::to_string(expected.height) + " to " +
                                std::to_string(frame.cols) + "x" + std::to_string(frame.rows));
  }
}

}  // namespace scbt
