#include "scbt/testing/peers_test_util.h"

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <random>
#include <stdexcept>

#include "scbt/peers/peer_common.h"

namespace scbt::testing {

cv::Mat random_texture(cv::Size size, unsigned seed, int num_rectangles) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> grey(0, 255);
  std::uniform_int_distribution<int> x(0, size.width - 1), y(0, size.height - 1);
  std::uniform_int_distribution<int> side(4, std::max(5, std::min(size.width, size.height) / 4));
  cv::Mat texture(size, CV_8UC1, cv::Scalar(grey(rng)));
  for (int i = 0; i < num_rectangles; ++i) {
    const cv::Rect r(x(rng), y(rng), side(rng), side(rng));
    cv::rectangle(texture, r, cv::Scalar(grey(rng)), cv::FILLED);
  }
  cv::GaussianBlur(texture, texture, cv::Size(0, 0), 1.0);
  return texture;
}

cv::Mat frame_motion(int k, const Point& center, const Point& step, double degrees_per_frame) {
  cv::Mat rotation = cv::Mat::eye(3, 3, CV_64F);
  cv::getRotationMatrix2D(center, k * degrees_per_frame, 1.0)
      .copyTo(rotation(cv::Rect(0, 0, 3, 2)));
  cv::Mat translation = cv::Mat::eye(3, 3, CV_64F);
  translation.at<double>(0, 2) = k * step.x;
  translation.at<double>(1, 2) = k * step.y;
  return translation * rotation;
}

MovingPatch render_moving_patch(int num_frames, const Point& step, double degrees_per_frame,
                                unsigned seed, cv::Size patch_size, const Point& origin) {
  const cv::Size frame_size(640, 480);
  const cv::Mat background = random_texture(frame_size, seed * 7919u + 1u, 600);
  // A lighter, busier patch so that it differs from the background.
  cv::Mat patch = random_texture(patch_size, seed, 120);
  const Polygon corners0 = {origin, origin + Point(patch_size.width, 0),
                            origin + Point(patch_size.width, patch_size.height),
                            origin + Point(0, patch_size.height)};
  const Point center = origin + Point(0.5 * patch_size.width, 0.5 * patch_size.height);
  cv::Mat place = cv::Mat::eye(3, 3, CV_64F);
  place.at<double>(0, 2) = origin.x;
  place.at<double>(1, 2) = origin.y;

  MovingPatch scene;
  for (int k = 0; k < num_frames; ++k) {
    const cv::Mat motion = frame_motion(k, center, step, degrees_per_frame);
    const cv::Mat warp = motion * place;  // patch pixel -> frame pixel
    cv::Mat frame = background.clone();
    cv::warpPerspective(patch, frame, warp, frame_size, cv::INTER_LINEAR, cv::BORDER_TRANSPARENT);
    cv::Mat bgr;
    cv::cvtColor(frame, bgr, cv::COLOR_GRAY2BGR);
    scene.frames.push_back(bgr);
    scene.truth.push_back(apply_homography(motion, corners0));
  }
  return scene;
}

double mean_vertex_error(const Polygon& a, const Polygon& b) {
  if (a.size() != b.size() || a.empty()) throw std::invalid_argument("polygon sizes differ");
  double sum = 0.0;
  for (size_t i = 0; i < a.size(); ++i) sum += cv::norm(a[i] - b[i]);
  return sum / a.size();
}

}  // namespace scbt::testing
