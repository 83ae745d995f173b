#include "scbt/peers/csrt_tracker.h"

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <opencv2/tracking.hpp>
#include <stdexcept>
#include <string>

#include "scbt/peers/peer_common.h"

namespace scbt {
namespace {

// CSRT uses colour features: give it three channels whatever the input.
cv::Mat to_bgr(const cv::Mat& frame) {
  if (frame.channels() == 3) return frame;
  cv::Mat bgr;
  cv::cvtColor(frame, bgr, frame.channels() == 1 ? cv::COLOR_GRAY2BGR : cv::COLOR_BGRA2BGR);
  return bgr;
}

}  // namespace

void CsrtTrackerOptions::check() const {
  if (!(max_area_factor > 1.0)) {
    throw std::invalid_argument("csrt max_area_factor must be > 1, got " +
                                std::to_string(max_area_factor));
  }
}

CsrtTracker::CsrtTracker(const CsrtTrackerOptions& options) : options_(options) {
  options_.check();
}

CsrtTracker::~CsrtTracker() = default;

void CsrtTracker::init(const cv::Mat& frame, const Polygon& polygon) {
  cv::Mat gray;
  check_tracker_init(frame, polygon, &gray);
  frame_size_ = frame.size();
  polygon0_ = polygon;
  area0_ = area(polygon);
  const cv::Rect2d box = bounding_box(polygon);
  // CSRT works on integer boxes; round outwards and keep inside the frame.
  const cv::Rect ibox =
      cv::Rect(cv::Point(static_cast<int>(std::floor(box.x)), static_cast<int>(std::floor(box.y))),
               cv::Point(static_cast<int>(std::ceil(box.x + box.width)),
                         static_cast<int>(std::ceil(box.y + box.height)))) &
      cv::Rect(cv::Point(0, 0), frame_size_);
  if (ibox.width < 2 || ibox.height < 2) {
    throw std::invalid_argument("polygon's bounding box is too small for csrt");
  }
  box0_ = cv::Rect2d(ibox);
  cv::TrackerCSRT::Params params;
  tracker_ = cv::TrackerCSRT::create(params);
  tracker_->init(to_bgr(frame), ibox);
  boundary_ = polygon;
}

TrackResult CsrtTracker::track(const cv::Mat& frame) {
  if (!tracker_) throw std::logic_error("CsrtTracker::track called before init");
  const Stopwatch watch;
  TrackResult result;
  cv::Mat gray;
  to_gray(frame, &gray);  // the common frame checks
  check_frame_size(frame, frame_size_);

  bool ok = false;
  cv::Rect box;
  try {
    ok = tracker_->update(to_bgr(frame), box);
  } catch (const cv::Exception&) {
    ok = false;
  }
  if (ok && box.width > 0 && box.height > 0) {
    const double scale =
        std::sqrt(static_cast<double>(box.width) * box.height / (box0_.width * box0_.height));
    const Point c0(box0_.x + 0.5 * box0_.width, box0_.y + 0.5 * box0_.height);
    const Point c(box.x + 0.5 * box.width, box.y + 0.5 * box.height);
    Polygon candidate;
    candidate.reserve(polygon0_.size());
    for (const Point& p : polygon0_) candidate.push_back(c + scale * (p - c0));
    ok = plausible_update(candidate, area0_, frame_size_, options_.max_area_factor);
    if (ok) boundary_ = std::move(candidate);
  } else {
    ok = false;
  }
  result.held = !ok;
  result.boundary = boundary_;
  result.grouping_ms = watch.elapsed_ms();
  return result;
}

}  // namespace scbt
