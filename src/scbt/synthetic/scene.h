// Synthetic test scenes rendered in code: a textureless closed outline (a cup-rim-like ellipse, a
// box face or a random star-shaped polygon) moving, rotating and scaling over a cluttered, noisy
// background, with the exact boundary of every frame known. They are the built-in demo input and
// the ground truth of the end-to-end tracking tests.
#pragma once

#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

#include "scbt/geometry/polygon.h"

namespace scbt {

enum class SceneShape {
  kRim,      // an ellipse (a cup rim seen at an angle) approximated by many vertices
  kBox,      // a box face seen in mild perspective: a trapezoid-like quadrilateral
  kPolygon,  // a random star-shaped polygon of 5 to 8 vertices drawn from the seed
};

// Parses "rim", "box" or "polygon"; throws std::invalid_argument otherwise.
SceneShape parse_scene_shape(const std::string& name);
std::string to_string(SceneShape shape);

struct SceneOptions {
  cv::Size size{640, 480};
  std::uint32_t seed = 1;  // everything random (clutter, noise, random shape) derives from it
  SceneShape shape = SceneShape::kRim;
  double object_size = 80.0;  // half the object's longest extent at scale 1 (pixels)
  int rim_vertices = 72;      // vertices approximating the rim ellipse
  // Grey levels: the object is flat (textureless); the background is a smooth shading whose
  // clutter stays at least `min_contrast` away from the object's level.
  int object_level = 215;
  int min_contrast = 45;
  int clutter_strokes = 40;  // lines, rectangles and blobs in the background
  double near_share = 0.25;  // share of the clutter placed close to the object's path
  double blur_sigma = 0.8;   // mild optical blur (0: none)
  double noise_sigma = 5.0;  // additive Gaussian noise per frame (grey levels)

  // Throws std::invalid_argument naming the first bad value.
  void check() const;
};

// Where the object is: model point p maps to translation + scale * R(rotation) * p, R rotating
// by `rotation` radians (clockwise as drawn, since the image y axis points down).
struct Pose {
  Point translation{320.0, 240.0};
  double rotation = 0.0;
  double scale = 1.0;
};

Point apply_pose(const Pose& pose, const Point& model_point);
Polygon apply_pose(const Pose& pose, const Polygon& model);

// The object's outline in model coordinates, centred on the origin (deterministic per seed).
Polygon object_model(const SceneOptions& options);

// The static background: shading plus clutter. `near_region` (image coordinates) is where the
// object will move; near_share of the clutter is placed around it, the rest anywhere.
// Returns an 8-bit single-channel image of options.size, deterministic per (options, region).
cv::Mat render_background(const SceneOptions& options, const cv::Rect2d& near_region);

struct SceneFrame {
  cv::Mat image;  // 8-bit BGR (grey content; BGR so it goes through the colour code path)
  Polygon truth;  // the object's true outline in this frame
};

// Draws the object at `pose` over `background` with sub-pixel anti-aliasing, then blurs and adds
// noise seeded by (options.seed, frame_index).
SceneFrame render_frame(const SceneOptions& options, const cv::Mat& background,
                        const Polygon& model, const Pose& pose, int frame_index);

// One frame on its own background (clutter near the object placed around its pose).
SceneFrame render_frame(const SceneOptions& options, const Pose& pose, int frame_index = 0);

// The bounding box of the object's outline over all poses (empty for no poses).
cv::Rect2d path_region(const Polygon& model, const std::vector<Pose>& poses);

// A clip: one frame per pose over one static background, clutter near the whole path
// (render_background(options, path_region(...)) then render_frame per pose). Holds every frame in
// memory; long clips are better rendered frame by frame the same way.
std::vector<SceneFrame> render_clip(const SceneOptions& options, const std::vector<Pose>& poses);

struct MotionOptions {
  Pose start;                       // pose of the first frame
  Point amplitude{110.0, 60.0};     // translation swing around the start (pixels)
  double rotation_amplitude = 0.5;  // radians
  double scale_amplitude = 0.15;    // scale swings in [1 - a, 1 + a] times start.scale
  int period = 150;                 // frames per full translation cycle

  void check() const;
};

// A smooth path: Lissajous-like translation, sinusoidal rotation and scale, starting exactly at
// options.start. With the defaults the boundary moves at most about 5 px per frame.
std::vector<Pose> smooth_motion_path(const MotionOptions& options, int frames);

// Constant translation by `shift` per frame, rotation and scale fixed.
std::vector<Pose> linear_motion_path(const Pose& start, const Point& shift, int frames);

// Points along the closed polyline so that consecutive points are at most `step` apart (the
// vertices included).
std::vector<Point> sample_boundary(const Polygon& polygon, double step);

// Symmetric mean boundary distance: the mean of distance_to_boundary from points sampled every
// `step` pixels along `a` to `b`, and from `b`'s samples to `a`, averaged. 0 for identical
// outlines; +infinity when either polygon has fewer than 2 vertices.
double mean_boundary_distance(const Polygon& a, const Polygon& b, double step = 1.0);

}  // namespace scbt
