#include "scbt/peers/klt_tracker.h"

#include <algorithm>
#include <cmath>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>
#include <stdexcept>
#include <string>

#include "scbt/peers/peer_common.h"

namespace scbt {
namespace {

int min_survivors(const KltTrackerOptions& options) {
  return std::max(8, static_cast<int>(std::ceil(options.redetect_fraction * options.max_features)));
}

}  // namespace

void KltTrackerOptions::check() const {
  if (max_features < 8) {
    throw std::invalid_argument("klt max_features must be >= 8, got " +
                                std::to_string(max_features));
  }
  if (!(quality_level > 0.0 && quality_level < 1.0)) {
    throw std::invalid_argument("klt quality_level must be in (0, 1), got " +
                                std::to_string(quality_level));
  }
  if (!(min_distance >= 0.0)) {
    throw std::invalid_argument("klt min_distance must be >= 0, got " +
                                std::to_string(min_distance));
  }
  if (window_size < 3 || window_size % 2 == 0) {
    throw std::invalid_argument("klt window_size must be odd and >= 3, got " +
                                std::to_string(window_size));
  }
  if (pyramid_levels < 0) {
    throw std::invalid_argument("klt pyramid_levels must be >= 0, got " +
                                std::to_string(pyramid_levels));
  }
  if (!(ransac_threshold > 0.0)) {
    throw std::invalid_argument("klt ransac_threshold must be > 0, got " +
                                std::to_string(ransac_threshold));
  }
  if (!(redetect_fraction >= 0.0 && redetect_fraction <= 1.0)) {
    throw std::invalid_argument("klt redetect_fraction must be in [0, 1], got " +
                                std::to_string(redetect_fraction));
  }
  if (!(max_area_factor > 1.0)) {
    throw std::invalid_argument("klt max_area_factor must be > 1, got " +
                                std::to_string(max_area_factor));
  }
}

KltTracker::KltTracker(const KltTrackerOptions& options) : options_(options) { options_.check(); }

void KltTracker::init(const cv::Mat& frame, const Polygon& polygon) {
  cv::Mat gray;
  check_tracker_init(frame, polygon, &gray);
  frame_size_ = frame.size();
  polygon0_ = polygon;
  area0_ = area(polygon);
  boundary_ = polygon;
  warp_ = cv::Mat::eye(3, 3, CV_64F);
  reference_.clear();
  current_.clear();
  detect_features(gray);
  previous_gray_ = gray.clone();
}

void KltTracker::detect_features(const cv::Mat& gray) {
  const int wanted = options_.max_features - static_cast<int>(current_.size());
  if (wanted <= 0) return;
  cv::Mat mask = cv::Mat::zeros(gray.size(), CV_8U);
  std::vector<cv::Point> outline;
  for (const Point& p : boundary_) outline.emplace_back(cvRound(p.x), cvRound(p.y));
  cv::fillPoly(mask, std::vector<std::vector<cv::Point>>{outline}, cv::Scalar(255));
  // Keep new features away from the ones still tracked.
  for (const cv::Point2f& p : current_) {
    cv::circle(mask, p, std::max(1, cvRound(options_.min_distance)), cv::Scalar(0), cv::FILLED);
  }
  std::vector<cv::Point2f> found;
  cv::goodFeaturesToTrack(gray, found, wanted, options_.quality_level, options_.min_distance, mask);
  if (found.empty()) return;
  std::vector<cv::Point2f> back;
  cv::perspectiveTransform(found, back, warp_.inv());
  for (size_t i = 0; i < found.size(); ++i) {
    if (!std::isfinite(back[i].x) || !std::isfinite(back[i].y)) continue;
    current_.push_back(found[i]);
    reference_.push_back(back[i]);
  }
}

TrackResult KltTracker::track(const cv::Mat& frame) {
  if (boundary_.empty()) throw std::logic_error("KltTracker::track called before init");
  const Stopwatch watch;
  TrackResult result;
  cv::Mat gray;
  to_gray(frame, &gray);
  check_frame_size(frame, frame_size_);

  bool ok = false;
  if (!current_.empty()) {
    const cv::Size window(options_.window_size, options_.window_size);
    const cv::TermCriteria criteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 30, 0.01);
    std::vector<cv::Point2f> next;
    std::vector<uchar> status;
    std::vector<float> error;
    cv::calcOpticalFlowPyrLK(previous_gray_, gray, current_, next, status, error, window,
                             options_.pyramid_levels, criteria);
    std::vector<uchar> back_status(status.size(), 1);
    std::vector<cv::Point2f> back;
    if (options_.max_forward_backward_error > 0.0) {
      back = current_;
      cv::calcOpticalFlowPyrLK(gray, previous_gray_, next, back, back_status, error, window,
                               options_.pyramid_levels, criteria, cv::OPTFLOW_USE_INITIAL_FLOW);
    }
    std::vector<cv::Point2f> kept_reference;
    std::vector<cv::Point2f> kept_current;
    const cv::Rect2f inside(0, 0, static_cast<float>(frame.cols), static_cast<float>(frame.rows));
    for (size_t i = 0; i < current_.size(); ++i) {
      if (!status[i] || !back_status[i] || !inside.contains(next[i])) continue;
      if (options_.max_forward_backward_error > 0.0 &&
          cv::norm(back[i] - current_[i]) > options_.max_forward_backward_error) {
        continue;
      }
      kept_reference.push_back(reference_[i]);
      kept_current.push_back(next[i]);
    }

    if (kept_current.size() >= 4) {
      std::vector<uchar> inliers;
      cv::Mat h;
      try {
        h = cv::findHomography(kept_reference, kept_current, cv::RANSAC, options_.ransac_threshold,
                               inliers);
      } catch (const cv::Exception&) {
        h.release();
      }
      if (!h.empty() && cv::checkRange(h)) {
        const Polygon candidate = apply_homography(h, polygon0_);
        if (plausible_update(candidate, area0_, frame_size_, options_.max_area_factor)) {
          warp_ = h;
          boundary_ = candidate;
          ok = true;
          // RANSAC outliers are dropped so they do not pollute the next estimates.
          size_t w = 0;
          for (size_t i = 0; i < kept_current.size(); ++i) {
            if (!inliers[i]) continue;
            kept_reference[w] = kept_reference[i];
            kept_current[w] = kept_current[i];
            ++w;
          }
          kept_reference.resize(w);
          kept_current.resize(w);
        }
      }
    }
    reference_ = std::move(kept_reference);
    current_ = std::move(kept_current);
  }

  if (static_cast<int>(current_.size()) < min_survivors(options_)) detect_features(gray);
  gray.copyTo(previous_gray_);

  result.held = !ok;
  result.boundary = boundary_;
  result.grouping_ms = watch.elapsed_ms();
  return result;
}

}  // namespace scbt
