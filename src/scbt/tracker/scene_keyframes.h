// Where a lost object's surroundings went: a few grey frames tracked with confidence, registered
// with the current frame by ORB features and a RANSAC similarity. After a jump in the video or a
// camera move while the object was hidden, the scene itself says where the object should be and how
// large (the object is assumed still in its scene; the search still checks its shape,
// tracker_lost.cc).
#pragma once

#include <opencv2/core/mat.hpp>
#include <optional>
#include <vector>

#include "scbt/geometry/polygon.h"

namespace scbt {

struct KeyframeOptions {
  int keep_every = 10;   // of the frames offered (tracked with confidence), every this-th is kept
  int min_age = 4;       // offers: a keyframe this recent may already show the loss coming
  int features = 800;    // ORB features per image
  double ratio = 0.8;    // Lowe's ratio test on the two nearest descriptors
  double ransac_px = 4;  // RANSAC inlier distance (pixels)
  int min_inliers = 12;  // fewer: no registration (a flat or unrelated view)
  double min_inlier_share = 0.25;  // of the matches passing the ratio test

  // Throws std::invalid_argument naming the first bad value.
  void check() const;
};

// The keyframe's boundary moved into the current frame by the registration.
struct RegisteredBoundary {
  Polygon boundary;
  double scale = 1.0;  // of the similarity: the scene's size now over its size then
};

// A similarity (scale, rotation, translation) taking `from` (8-bit grey, frame coordinates from
// `from_origin`) onto `to` (8-bit grey, a whole frame), or nullopt when the images do not share
// enough features. Exposed for tests; SceneKeyframes caches the keyframe's features.
std::optional<cv::Matx23d> register_views(const cv::Mat& from, cv::Point from_origin,
                                          const cv::Mat& to, const KeyframeOptions& options = {});

class SceneKeyframes {
 public:
  explicit SceneKeyframes(const KeyframeOptions& options = {});

  void clear();
  // A confidently tracked frame (8-bit grey, BGR or BGRA) and its boundary. Kept on every
  // keep_every-th call only: the whole frame, since the object alone may have changed (a cup
  // emptied) while its surroundings did not. Copied as given: the grey conversion and the
  // features wait until the object is lost (a whole-frame conversion on every tracked frame also
  // woke OpenCV's thread pool).
  void offer(const cv::Mat& frame, const Polygon& boundary);
  // The newest keyframe at least min_age offers old (else the other) registered with `frame`
  // (8-bit grey, the whole frame): its boundary there, or nullopt.
  std::optional<RegisteredBoundary> locate(const cv::Mat& frame);
  // The keyframe locate() registers: its image (as offered) and boundary; false when none is kept.
  bool view(cv::Mat* image, Polygon* boundary) const;

 private:
  struct Keyframe {
    cv::Mat image;  // as offered
    Polygon boundary;
    int offered_at = -1;  // -1: empty
    bool described = false;
    std::vector<cv::KeyPoint> points;
    cv::Mat descriptors;
  };
  KeyframeOptions options_;
  // The slot locate() and view() use: the newest at least min_age offers old, else the other
  // (-1: none kept).
  int chosen_slot() const;
  Keyframe slots_[2];
  int newest_ = 0;
  int offers_ = 0;
  std::vector<cv::KeyPoint> frame_points_;
  cv::Mat frame_descriptors_;
};

}  // namespace scbt
