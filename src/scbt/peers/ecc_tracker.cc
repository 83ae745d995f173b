#include "scbt/peers/ecc_tracker.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "scbt/peers/peer_common.h"

namespace scbt {
namespace {

// Pixel coordinates of an image resized by factor s, from those of the original: pixel centres
// map as x' + 0.5 = s (x + 0.5).
cv::Mat level_matrix(double s) {
  cv::Mat m = cv::Mat::eye(3, 3, CV_64F);
  m.at<double>(0, 0) = s;
  m.at<double>(1, 1) = s;
  m.at<double>(0, 2) = 0.5 * s - 0.5;
  m.at<double>(1, 2) = 0.5 * s - 0.5;
  return m;
}

cv::Mat translation_matrix(double tx, double ty) {
  cv::Mat m = cv::Mat::eye(3, 3, CV_64F);
  m.at<double>(0, 2) = tx;
  m.at<double>(1, 2) = ty;
  return m;
}

// The polygon's bounding box grown by `margin` on every side, clipped to the frame.
cv::Rect grown_box(const Polygon& polygon, double margin, const cv::Size& size) {
  const cv::Rect2d box = bounding_box(polygon);
  const int x0 = static_cast<int>(std::floor(box.x - margin));
  const int y0 = static_cast<int>(std::floor(box.y - margin));
  const int x1 = static_cast<int>(std::ceil(box.x + box.width + margin));
  const int y1 = static_cast<int>(std::ceil(box.y + box.height + margin));
  return cv::Rect(cv::Point(x0, y0), cv::Point(x1, y1)) & cv::Rect(cv::Point(0, 0), size);
}

}  // namespace

void EccTrackerOptions::check() const {
  if (template_margin < 0) {
    throw std::invalid_argument("ecc template_margin must be >= 0, got " +
                                std::to_string(template_margin));
  }
  if (min_template_side < 8 || max_template_side < min_template_side) {
    throw std::invalid_argument("ecc template sides must satisfy 8 <= min (" +
                                std::to_string(min_template_side) + ") <= max (" +
                                std::to_string(max_template_side) + ")");
  }
  if (max_levels < 1) {
    throw std::invalid_argument("ecc max_levels must be >= 1, got " + std::to_string(max_levels));
  }
  if (max_iterations < 1) {
    throw std::invalid_argument("ecc max_iterations must be >= 1, got " +
                                std::to_string(max_iterations));
  }
  if (!(epsilon >= 0.0)) {
    throw std::invalid_argument("ecc epsilon must be >= 0, got " + std::to_string(epsilon));
  }
  if (gauss_filter_size < 1 || gauss_filter_size % 2 == 0) {
    throw std::invalid_argument("ecc gauss_filter_size must be odd and >= 1, got " +
                                std::to_string(gauss_filter_size));
  }
  if (!(max_area_factor > 1.0)) {
    throw std::invalid_argument("ecc max_area_factor must be > 1, got " +
                                std::to_string(max_area_factor));
  }
}

EccTracker::EccTracker(const EccTrackerOptions& options) : options_(options) { options_.check(); }

void EccTracker::init(const cv::Mat& frame, const Polygon& polygon) {
  cv::Mat gray;
  check_tracker_init(frame, polygon, &gray);
  frame_size_ = frame.size();
  const cv::Rect box = grown_box(polygon, options_.template_margin, frame_size_);
  cv::Mat full;
  gray(box).convertTo(full, CV_32F);

  templates_.clear();
  scales_.clear();
  const int side = std::max(box.width, box.height);
  double scale = std::min(1.0, static_cast<double>(options_.max_template_side) / side);
  while (static_cast<int>(templates_.size()) < options_.max_levels) {
    cv::Mat level;
    if (scale == 1.0) {
      level = full;
    } else {
      cv::resize(full, level, cv::Size(), scale, scale, cv::INTER_AREA);
    }
    if (level.cols < 4 || level.rows < 4) break;
    templates_.push_back(level);
    scales_.push_back(scale);
    scale *= 0.5;
    if (side * scale < options_.min_template_side) break;
  }

  polygon0_.clear();
  for (const Point& p : polygon) polygon0_.emplace_back(p.x - box.x, p.y - box.y);
  area0_ = area(polygon);
  warp_ = translation_matrix(box.x, box.y);
  boundary_ = polygon;
}

TrackResult EccTracker::track(const cv::Mat& frame) {
  if (boundary_.empty()) throw std::logic_error("EccTracker::track called before init");
  const Stopwatch watch;
  TrackResult result;
  cv::Mat gray;
  to_gray(frame, &gray);
  check_frame_size(frame, frame_size_);

  // Search only around the previous boundary: the crop keeps the per-frame cost independent of
  // the frame size.
  const cv::Rect2d prev_box = bounding_box(boundary_);
  const double reach = 0.5 * std::max(prev_box.width, prev_box.height) + 16.0;
  const cv::Rect crop = grown_box(boundary_, reach, frame_size_);

  cv::Mat warp = translation_matrix(-crop.x, -crop.y) * warp_;  // template -> crop coordinates
  bool ok = crop.width >= 8 && crop.height >= 8;
  if (ok) {
    cv::Mat input;
    gray(crop).convertTo(input, CV_32F);
    // Only input pixels inside the previous boundary (grown by a few pixels, to keep its edges)
    // take part, so the background the template's bounding box also holds does not pull the warp.
    cv::Mat mask(crop.size(), CV_8U, cv::Scalar(options_.mask_growth < 0 ? 255 : 0));
    std::vector<cv::Point> outline;
    for (const Point& p : boundary_)
      outline.emplace_back(cvRound(p.x - crop.x), cvRound(p.y - crop.y));
    if (options_.mask_growth >= 0)
      cv::fillPoly(mask, std::vector<std::vector<cv::Point>>{outline}, cv::Scalar(255));
    if (options_.mask_growth > 0) {
      cv::dilate(
          mask, mask,
          cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * options_.mask_growth + 1,
                                                                2 * options_.mask_growth + 1)));
    }
    // A coarse level that fails (ECC throws when the correlation would decrease) leaves the warp
    // as it was; only a failure at the finest level holds the frame.
    for (int level = static_cast<int>(templates_.size()) - 1; level >= 0; --level) {
      ok = true;
      const double s = scales_[level];
      cv::Mat scaled_input, scaled_mask;
      if (s == 1.0) {
        scaled_input = input;
        scaled_mask = mask;
      } else {
        cv::resize(input, scaled_input, cv::Size(), s, s, cv::INTER_AREA);
        cv::resize(mask, scaled_mask, scaled_input.size(), 0, 0, cv::INTER_NEAREST);
      }
      if (scaled_input.cols < 4 || scaled_input.rows < 4) continue;
      // Both images are resized by s, so the level's warp is L * W * L^-1.
      const cv::Mat to_level = level_matrix(s);
      const cv::Mat from_level = to_level.inv();
      cv::Mat level_warp;
      cv::Mat(to_level * warp * from_level).convertTo(level_warp, CV_32F);
      try {
        cv::findTransformECC(templates_[level], scaled_input, level_warp, cv::MOTION_HOMOGRAPHY,
                             cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS,
                                              options_.max_iterations, options_.epsilon),
                             scaled_mask, options_.gauss_filter_size);
      } catch (const cv::Exception&) {
        ok = false;  // did not converge, or the warp became singular
        continue;
      }
      cv::Mat refined;
      level_warp.convertTo(refined, CV_64F);
      if (!cv::checkRange(refined)) {
        ok = false;
        continue;
      }
      warp = from_level * refined * to_level;
    }
  }

  if (ok) {
    const cv::Mat candidate_warp = translation_matrix(crop.x, crop.y) * warp;
    const Polygon candidate = apply_homography(candidate_warp, polygon0_);
    if (cv::checkRange(candidate_warp) &&
        plausible_update(candidate, area0_, frame_size_, options_.max_area_factor)) {
      warp_ = candidate_warp;
      boundary_ = candidate;
    } else {
      ok = false;
    }
  }
  result.held = !ok;
  result.boundary = boundary_;
  result.grouping_ms = watch.elapsed_ms();
  return result;
}

}  // namespace scbt
