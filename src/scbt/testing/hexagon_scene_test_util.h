// Shared by the tracker's image-motion tests (recovery, prediction): a flat, dark hexagon on a
// textured table larger than the camera's view, so that the view can pan and image motion is
// measurable.
#pragma once

#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "scbt/geometry/polygon.h"

namespace scbt {

inline Polygon hexagon(Point center, double radius) {
  Polygon polygon;
  for (int k = 0; k < 6; ++k) {
    const double angle = CV_PI / 3.0 * k + 0.2;
    polygon.emplace_back(center.x + radius * std::cos(angle), center.y + radius * std::sin(angle));
  }
  return polygon;
}

// 960x720 grey texture with hexagon({480, 360}, 70) filled dark.
inline cv::Mat render_hexagon_scene(unsigned seed) {
  cv::Mat scene(720, 960, CV_8U);
  cv::RNG rng(seed);
  rng.fill(scene, cv::RNG::UNIFORM, 90, 200);
  cv::GaussianBlur(scene, scene, cv::Size(0, 0), 3.0);
  std::vector<cv::Point> points;
  for (const Point& p : hexagon({480, 360}, 70)) points.emplace_back(cvRound(p.x), cvRound(p.y));
  cv::fillPoly(scene, std::vector<std::vector<cv::Point>>{points}, cv::Scalar(20), cv::LINE_AA);
  return scene;
}

}  // namespace scbt
