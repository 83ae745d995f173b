#include "scbt/tracker/scene_keyframes.h"

#include <cmath>
#include <opencv2/calib3d.hpp>
#include <opencv2/features2d.hpp>
#include <stdexcept>
#include <string>

#include "scbt/tracker/frame_checks.h"

namespace scbt {
namespace {

// Scales outside this are not a camera move between two views of one scene but a bad fit.
constexpr double kMinScale = 0.25;
constexpr double kMaxScale = 4.0;

cv::Ptr<cv::ORB> make_orb(const KeyframeOptions& options) {
  return cv::ORB::create(options.features);
}

// The similarity taking the `from` features (image at `from_origin`) onto the `to` ones.
std::optional<cv::Matx23d> match_similarity(const std::vector<cv::KeyPoint>& from_points,
                                            const cv::Mat& from_descriptors, cv::Point from_origin,
                                            const std::vector<cv::KeyPoint>& to_points,
                                            const cv::Mat& to_descriptors,
                                            const KeyframeOptions& options) {
  if (from_descriptors.rows < options.min_inliers || to_descriptors.rows < options.min_inliers) {
    return std::nullopt;
  }
  cv::BFMatcher matcher(cv::NORM_HAMMING);
  std::vector<std::vector<cv::DMatch>> pairs;
  matcher.knnMatch(from_descriptors, to_descriptors, pairs, 2);
  std::vector<cv::Point2f> from, to;
  for (const std::vector<cv::DMatch>& pair : pairs) {
    if (pair.size() < 2 || pair[0].distance >= options.ratio * pair[1].distance) continue;
    from.push_back(from_points[pair[0].queryIdx].pt + cv::Point2f(from_origin));
    to.push_back(to_points[pair[0].trainIdx].pt);
  }
  if (static_cast<int>(from.size()) < options.min_inliers) return std::nullopt;
  std::vector<uchar> inlier;
  const cv::Mat m =
      cv::estimateAffinePartial2D(from, to, inlier, cv::RANSAC, options.ransac_px, 2000, 0.995);
  if (m.empty()) return std::nullopt;
  const int inliers = cv::countNonZero(inlier);
  if (inliers < options.min_inliers || inliers < options.min_inlier_share * from.size()) {
    return std::nullopt;
  }
  const cv::Matx23d similarity(m);
  const double scale = std::hypot(similarity(0, 0), similarity(1, 0));
  if (!(scale >= kMinScale && scale <= kMaxScale)) return std::nullopt;
  return similarity;
}

}  // namespace

void KeyframeOptions::check() const {
  if (keep_every < 1 || min_age < 0 || features < 16 || !(ratio > 0.0 && ratio <= 1.0) ||
      !(ransac_px > 0.0) || min_inliers < 3 ||
      !(min_inlier_share >= 0.0 && min_inlier_share <= 1.0)) {
    throw std::invalid_argument(
        "KeyframeOptions: keep_every >= 1, min_age >= 0, features >= 16, ratio in (0, 1], "
        "ransac_px > 0, min_inliers >= 3 and min_inlier_share in [0, 1] are required");
  }
}

std::optional<cv::Matx23d> register_views(const cv::Mat& from, cv::Point from_origin,
                                          const cv::Mat& to, const KeyframeOptions& options) {
  cv::Ptr<cv::ORB> orb = make_orb(options);
  std::vector<cv::KeyPoint> from_points, to_points;
  cv::Mat from_descriptors, to_descriptors;
  orb->detectAndCompute(from, cv::noArray(), from_points, from_descriptors);
  orb->detectAndCompute(to, cv::noArray(), to_points, to_descriptors);
  return match_similarity(from_points, from_descriptors, from_origin, to_points, to_descriptors,
                          options);
}

SceneKeyframes::SceneKeyframes(const KeyframeOptions& options) : options_(options) {
  options_.check();
}

void SceneKeyframes::clear() {
  for (Keyframe& k : slots_) k.offered_at = -1;
  offers_ = 0;
}

void SceneKeyframes::offer(const cv::Mat& frame, const Polygon& boundary) {
  if (offers_++ % options_.keep_every != 0 || frame.empty()) return;
  newest_ = 1 - newest_;
  Keyframe& k = slots_[newest_];
  frame.copyTo(k.image);  // into the slot's buffer, reused from keyframe to keyframe
  k.boundary = boundary;
  k.offered_at = offers_ - 1;
  k.described = false;
}

int SceneKeyframes::chosen_slot() const {
  int slot = newest_;
  if (slots_[slot].offered_at < 0 || offers_ - slots_[slot].offered_at < options_.min_age) {
    slot = 1 - newest_;
  }
  if (slots_[slot].offered_at < 0) slot = newest_;
  return slots_[slot].offered_at < 0 ? -1 : slot;
}

bool SceneKeyframes::view(cv::Mat* image, Polygon* boundary) const {
  const int slot = chosen_slot();
  if (slot < 0) return false;
  *image = slots_[slot].image;
  *boundary = slots_[slot].boundary;
  return true;
}

std::optional<RegisteredBoundary> SceneKeyframes::locate(const cv::Mat& frame) {
  const int slot = chosen_slot();
  if (slot < 0) return std::nullopt;
  Keyframe* k = &slots_[slot];
  cv::Ptr<cv::ORB> orb = make_orb(options_);  // cheap to make; keeps OpenCV's features2d private
  if (!k->described) {
    cv::Mat gray;
    to_gray(k->image, &gray);
    orb->detectAndCompute(gray, cv::noArray(), k->points, k->descriptors);
    k->described = true;
  }
  orb->detectAndCompute(frame, cv::noArray(), frame_points_, frame_descriptors_);
  const std::optional<cv::Matx23d> m = match_similarity(
      k->points, k->descriptors, cv::Point(0, 0), frame_points_, frame_descriptors_, options_);
  if (!m) return std::nullopt;
  RegisteredBoundary out;
  const cv::Matx23d& s = *m;
  for (const Point& p : k->boundary) {
    out.boundary.emplace_back(s(0, 0) * p.x + s(0, 1) * p.y + s(0, 2),
                              s(1, 0) * p.x + s(1, 1) * p.y + s(1, 2));
  }
  out.scale = std::hypot(s(0, 0), s(1, 0));
  return out;
}

}  // namespace scbt
