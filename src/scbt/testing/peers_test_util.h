// Synthetic scenes for the peer tracker tests: a randomly textured planar patch moved over a
// differently textured background, rendered in code.
#pragma once

#include <opencv2/core/mat.hpp>
#include <vector>

#include "scbt/geometry/polygon.h"

namespace scbt::testing {

// Random rectangles of random grey levels, smoothed: a texture with corners and edges everywhere.
cv::Mat random_texture(cv::Size size, unsigned seed, int num_rectangles);

// Rigid motion of frame k: rotation by k * degrees_per_frame about `center`, then translation
// by k * step.
cv::Mat frame_motion(int k, const Point& center, const Point& step, double degrees_per_frame);

struct MovingPatch {
  std::vector<cv::Mat> frames;  // BGR 640x480
  std::vector<Polygon> truth;   // the patch's outline in every frame
};

// A `patch_size` textured patch whose top-left starts at `origin`, moved by frame_motion over
// `num_frames` frames on a background texture.
MovingPatch render_moving_patch(int num_frames, const Point& step, double degrees_per_frame,
                                unsigned seed, cv::Size patch_size = {160, 120},
                                const Point& origin = {200, 160});

// Mean distance between corresponding vertices.
double mean_vertex_error(const Polygon& a, const Polygon& b);

}  // namespace scbt::testing
