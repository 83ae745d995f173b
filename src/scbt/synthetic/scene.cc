#include "scbt/synthetic/scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <random>
#include <stdexcept>

namespace scbt {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Sub-rows per pixel row when integrating the object's coverage: the coverage is exact across
// each sub-row and midpoint-sampled down the rows.
constexpr int kSubRows = 16;

std::string number(double value) { return std::to_string(value); }

// Independent, deterministic random streams derived from the seed.
std::uint64_t stream_seed(std::uint32_t seed, std::uint64_t stream) {
  std::uint64_t z = (static_cast<std::uint64_t>(seed) << 32) ^ (stream * 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

enum Stream : std::uint64_t { kShapeStream = 1, kBackgroundStream = 2, kNoiseStream = 1000 };

// The share of each pixel of `roi` inside `polygon` (even-odd rule), as CV_32F in [0, 1]. Pixel
// (x, y) covers [x - 0.5, x + 0.5] x [y - 0.5, y + 0.5]. OpenCV's fillPoly is not used because it
// fills boundary pixels inclusively, which grows the shape by half a pixel of its grid.
cv::Mat polygon_coverage(const Polygon& polygon, const cv::Rect& roi) {
  cv::Mat coverage = cv::Mat::zeros(roi.size(), CV_32F);
  const size_t n = polygon.size();
  std::vector<double> crossings;
  for (int r = 0; r < roi.height; ++r) {
    float* row = coverage.ptr<float>(r);
    const double y = roi.y + r;
    for (int s = 0; s < kSubRows; ++s) {
      const double yc = y - 0.5 + (s + 0.5) / kSubRows;
      crossings.clear();
      for (size_t i = 0; i < n; ++i) {
        const Point& a = polygon[i];
        const Point& b = polygon[(i + 1) % n];
        if ((a.y <= yc) != (b.y <= yc)) {
          crossings.push_back(a.x + (yc - a.y) * (b.x - a.x) / (b.y - a.y));
        }
      }
      std::sort(crossings.begin(), crossings.end());
      for (size_t k = 0; k + 1 < crossings.size(); k += 2) {
        const double x0 = crossings[k] - roi.x;
        const double x1 = crossings[k + 1] - roi.x;
        const int c0 = std::max(0, static_cast<int>(std::floor(x0 + 0.5)));
        const int c1 = std::min(roi.width - 1, static_cast<int>(std::floor(x1 + 0.5)));
        for (int c = c0; c <= c1; ++c) {
          const double overlap = std::min(x1, c + 0.5) - std::max(x0, c - 0.5);
          if (overlap > 0.0) row[c] += static_cast<float>(overlap / kSubRows);
        }
      }
    }
  }
  return coverage;
}

// The grey-level interval clutter and shading are drawn from: the side of object_level with more
// room, at least min_contrast away from it.
void background_levels(const SceneOptions& options, int* low, int* high) {
  const int below = options.object_level - options.min_contrast;
  const int above = options.object_level + options.min_contrast;
  if (below >= 255 - above) {
    *low = std::min(15, below);
    *high = below;
  } else {
    *low = above;
    *high = std::max(240, above);
  }
}

}  // namespace

SceneShape parse_scene_shape(const std::string& name) {
  if (name == "rim") return SceneShape::kRim;
  if (name == "box") return SceneShape::kBox;
  if (name == "polygon") return SceneShape::kPolygon;
  throw std::invalid_argument("unknown scene shape \"" + name +
                              "\" (expected rim, box or polygon)");
}

std::string to_string(SceneShape shape) {
  switch (shape) {
    case SceneShape::kRim:
      return "rim";
    case SceneShape::kBox:
      return "box";
    case SceneShape::kPolygon:
      return "polygon";
  }
  return "unknown";
}

void SceneOptions::check() const {
  if (size.width < 64 || size.height < 64 || size.width > 8192 || size.height > 8192) {
    throw std::invalid_argument("scene size must be within 64..8192 per side, got " +
                                std::to_string(size.width) + "x" + std::to_string(size.height));
  }
  if (!(object_size >= 8.0 && object_size <= 0.5 * std::min(size.width, size.height))) {
    throw std::invalid_argument("object_size must be in [8, half the smaller image side], got " +
                                number(object_size));
  }
  if (rim_vertices < 8 || rim_vertices > 1000) {
    throw std::invalid_argument("rim_vertices must be in 8..1000, got " +
                                std::to_string(rim_vertices));
  }
  if (object_level < 0 || object_level > 255) {
    throw std::invalid_argument("object_level must be in 0..255, got " +
                                std::to_string(object_level));
  }
  if (min_contrast < 1 || min_contrast > 200) {
    throw std::invalid_argument("min_contrast must be in 1..200, got " +
                                std::to_string(min_contrast));
  }
  if (object_level - min_contrast < 0 && object_level + min_contrast > 255) {
    throw std::invalid_argument("min_contrast " + std::to_string(min_contrast) +
                                " leaves no background level for object_level " +
                                std::to_string(object_level));
  }
  if (clutter_strokes < 0 || clutter_strokes > 10000) {
    throw std::invalid_argument("clutter_strokes must be in 0..10000, got " +
                                std::to_string(clutter_strokes));
  }
  if (!(near_share >= 0.0 && near_share <= 1.0)) {
    throw std::invalid_argument("near_share must be in [0, 1], got " + number(near_share));
  }
  if (!(blur_sigma >= 0.0 && blur_sigma <= 10.0)) {
    throw std::invalid_argument("blur_sigma must be in [0, 10], got " + number(blur_sigma));
  }
  if (!(noise_sigma >= 0.0 && noise_sigma <= 100.0)) {
    throw std::invalid_argument("noise_sigma must be in [0, 100], got " + number(noise_sigma));
  }
}

void MotionOptions::check() const {
  if (!(start.scale > 0.0) || !std::isfinite(start.scale)) {
    throw std::invalid_argument("start scale must be positive, got " + number(start.scale));
  }
  if (!std::isfinite(start.translation.x) || !std::isfinite(start.translation.y) ||
      !std::isfinite(start.rotation)) {
    throw std::invalid_argument("start pose must be finite");
  }
  if (!std::isfinite(amplitude.x) || !std::isfinite(amplitude.y) ||
      !std::isfinite(rotation_amplitude)) {
    throw std::invalid_argument("motion amplitudes must be finite");
  }
  if (!(scale_amplitude >= 0.0 && scale_amplitude < 1.0)) {
    throw std::invalid_argument("scale_amplitude must be in [0, 1), got " +
                                number(scale_amplitude));
  }
  if (period < 2) {
    throw std::invalid_argument("period must be >= 2 frames, got " + std::to_string(period));
  }
}

Point apply_pose(const Pose& pose, const Point& p) {
  const double c = std::cos(pose.rotation) * pose.scale;
  const double s = std::sin(pose.rotation) * pose.scale;
  return {pose.translation.x + c * p.x - s * p.y, pose.translation.y + s * p.x + c * p.y};
}

Polygon apply_pose(const Pose& pose, const Polygon& model) {
  Polygon out;
  out.reserve(model.size());
  for (const Point& p : model) out.push_back(apply_pose(pose, p));
  return out;
}

Polygon object_model(const SceneOptions& options) {
  options.check();
  const double r = options.object_size;
  Polygon model;
  switch (options.shape) {
    case SceneShape::kRim: {
      // A cup rim seen from above at an angle: a 2:1 ellipse.
      const int n = options.rim_vertices;
      for (int i = 0; i < n; ++i) {
        const double t = 2.0 * kPi * i / n;
        model.emplace_back(r * std::cos(t), 0.5 * r * std::sin(t));
      }
      break;
    }
    case SceneShape::kBox:
      // The top face of a box in mild perspective: the far edge is shorter.
      model = {{-0.78 * r, -0.6 * r}, {0.78 * r, -0.6 * r}, {r, 0.6 * r}, {-r, 0.6 * r}};
      break;
    case SceneShape::kPolygon: {
      // Star-shaped around the origin (vertices in angular order), hence simple.
      std::mt19937 rng(static_cast<std::uint32_t>(stream_seed(options.seed, kShapeStream)));
      const int n = std::uniform_int_distribution<int>(5, 8)(rng);
      std::uniform_real_distribution<double> jitter(-0.25, 0.25);
      std::uniform_real_distribution<double> radius(0.6 * r, r);
      const double phase = std::uniform_real_distribution<double>(0.0, 2.0 * kPi)(rng);
      for (int i = 0; i < n; ++i) {
        const double t = phase + 2.0 * kPi * (i + jitter(rng)) / n;
        const double rho = radius(rng);
        model.emplace_back(rho * std::cos(t), rho * std::sin(t));
      }
      break;
    }
  }
  return model;
}

cv::Mat render_background(const SceneOptions& options, const cv::Rect2d& near_region) {
  options.check();
  int low = 0;
  int high = 0;
  background_levels(options, &low, &high);
  std::mt19937 rng(static_cast<std::uint32_t>(stream_seed(options.seed, kBackgroundStream)));
  auto uniform = [&rng](double a, double b) {
    return std::uniform_real_distribution<double>(a, b)(rng);
  };
  auto level = [&](double from, double to) {
    return cv::Scalar(std::round(low + (high - low) * uniform(from, to)));
  };

  // Smooth shading: a coarse random grid upsampled with cubic interpolation, kept in range.
  cv::Mat coarse(5, 6, CV_32F);
  for (int y = 0; y < coarse.rows; ++y) {
    for (int x = 0; x < coarse.cols; ++x) {
      coarse.at<float>(y, x) = static_cast<float>(low + (high - low) * uniform(0.35, 0.85));
    }
  }
  cv::Mat shading;
  cv::resize(coarse, shading, options.size, 0, 0, cv::INTER_CUBIC);
  cv::Mat background;
  shading.convertTo(background, CV_8U);
  cv::max(background, low, background);
  cv::min(background, high, background);

  const double w = options.size.width;
  const double h = options.size.height;
  const double extent = std::max(w, h);
  // Clutter near the object: centres in its region grown by a margin, so some strokes run
  // through or right beside the outline's path.
  const double margin = 40.0;
  const cv::Rect2d near(near_region.x - margin, near_region.y - margin,
                        near_region.width + 2 * margin, near_region.height + 2 * margin);
  for (int i = 0; i < options.clutter_strokes; ++i) {
    Point centre;
    const bool is_near = !near_region.empty() && uniform(0.0, 1.0) < options.near_share;
    if (is_near) {
      centre = {uniform(near.x, near.x + near.width), uniform(near.y, near.y + near.height)};
    } else {
      centre = {uniform(0.0, w), uniform(0.0, h)};
    }
    const double angle = uniform(0.0, kPi);
    const Point direction(std::cos(angle), std::sin(angle));
    const cv::Scalar colour = level(0.0, 1.0);
    const int kind = std::uniform_int_distribution<int>(0, 4)(rng);
    // Near strokes are shorter so that they sit beside the outline rather than mimic it.
    const double size = (is_near ? 0.04 : 0.06) * extent * uniform(0.5, 2.0);
    switch (kind) {
      case 0:
      case 1: {  // a straight stroke
        const int thickness = std::uniform_int_distribution<int>(1, 4)(rng);
        const Point a = centre - direction * size;
        const Point b = centre + direction * size;
        cv::line(background, a, b, colour, thickness, cv::LINE_AA);
        break;
      }
      case 2: {  // a rectangle outline or filled rectangle
        const cv::RotatedRect rect(centre, cv::Size2f(size, size * uniform(0.3, 1.0)),
                                   static_cast<float>(angle * 180.0 / kPi));
        cv::Point2f corners[4];
        rect.points(corners);
        std::vector<cv::Point> pts;
        for (const cv::Point2f& c : corners) pts.emplace_back(cvRound(c.x), cvRound(c.y));
        if (uniform(0.0, 1.0) < 0.5) {
          cv::fillConvexPoly(background, pts, colour, cv::LINE_AA);
        } else {
          cv::polylines(background, pts, true, colour, 2, cv::LINE_AA);
        }
        break;
      }
      case 3: {  // a blob
        const cv::Size axes(std::max(2, cvRound(0.5 * size)),
                            std::max(2, cvRound(0.5 * size * uniform(0.4, 1.0))));
        cv::ellipse(background, cv::Point(cvRound(centre.x), cvRound(centre.y)), axes,
                    angle * 180.0 / kPi, 0.0, 360.0, colour, cv::FILLED, cv::LINE_AA);
        break;
      }
      default: {  // a scribble: a short random polyline
        std::vector<cv::Point> pts;
        Point p = centre;
        for (int k = 0; k < 5; ++k) {
          pts.emplace_back(cvRound(p.x), cvRound(p.y));
          const double turn = uniform(0.0, 2.0 * kPi);
          p += Point(std::cos(turn), std::sin(turn)) * (0.4 * size);
        }
        cv::polylines(background, pts, false, colour, 1, cv::LINE_AA);
        break;
      }
    }
  }
  return background;
}

SceneFrame render_frame(const SceneOptions& options, const cv::Mat& background,
                        const Polygon& model, const Pose& pose, int frame_index) {
  options.check();
  if (background.type() != CV_8UC1 || background.size() != options.size) {
    throw std::invalid_argument("background must be 8-bit grey of the scene size");
  }
  if (model.size() < 3) throw std::invalid_argument("object model needs at least 3 vertices");
  SceneFrame frame;
  frame.truth = apply_pose(pose, model);

  cv::Mat image;
  background.convertTo(image, CV_32F);
  // Coverage of the object per pixel, from a supersampled binary fill inside its bounding box.
  const cv::Rect2d box = bounding_box(frame.truth);
  const cv::Rect roi = cv::Rect(cvFloor(box.x) - 2, cvFloor(box.y) - 2, cvCeil(box.width) + 5,
                                cvCeil(box.height) + 5) &
                       cv::Rect(0, 0, options.size.width, options.size.height);
  if (!roi.empty()) {
    const cv::Mat coverage = polygon_coverage(frame.truth, roi);
    cv::Mat patch = image(roi);
    // patch = patch * (1 - coverage) + level * coverage
    cv::Mat blended = patch.mul(1.0 - coverage) + coverage * options.object_level;
    blended.copyTo(patch);
  }
  if (options.blur_sigma > 0.0) {
    cv::GaussianBlur(image, image, cv::Size(0, 0), options.blur_sigma);
  }
  if (options.noise_sigma > 0.0) {
    cv::RNG rng(stream_seed(options.seed, kNoiseStream + static_cast<std::uint64_t>(frame_index)));
    cv::Mat noise(image.size(), CV_32F);
    rng.fill(noise, cv::RNG::NORMAL, 0.0, options.noise_sigma);
    image += noise;
  }
  cv::Mat grey;
  image.convertTo(grey, CV_8U);  // rounds and saturates
  cv::cvtColor(grey, frame.image, cv::COLOR_GRAY2BGR);
  return frame;
}

SceneFrame render_frame(const SceneOptions& options, const Pose& pose, int frame_index) {
  const Polygon model = object_model(options);
  const cv::Mat background = render_background(options, bounding_box(apply_pose(pose, model)));
  return render_frame(options, background, model, pose, frame_index);
}

cv::Rect2d path_region(const Polygon& model, const std::vector<Pose>& poses) {
  cv::Rect2d path;
  for (size_t i = 0; i < poses.size(); ++i) {
    const cv::Rect2d box = bounding_box(apply_pose(poses[i], model));
    path = i == 0 ? box : (path | box);
  }
  return path;
}

std::vector<SceneFrame> render_clip(const SceneOptions& options, const std::vector<Pose>& poses) {
  const Polygon model = object_model(options);
  const cv::Mat background = render_background(options, path_region(model, poses));
  std::vector<SceneFrame> frames;
  frames.reserve(poses.size());
  for (size_t i = 0; i < poses.size(); ++i) {
    frames.push_back(render_frame(options, background, model, poses[i], static_cast<int>(i)));
  }
  return frames;
}

std::vector<Pose> smooth_motion_path(const MotionOptions& options, int frames) {
  options.check();
  if (frames < 0) throw std::invalid_argument("frames must be >= 0, got " + std::to_string(frames));
  std::vector<Pose> poses;
  poses.reserve(frames);
  for (int k = 0; k < frames; ++k) {
    const double t = 2.0 * kPi * k / options.period;
    Pose pose;
    pose.translation = options.start.translation + Point(options.amplitude.x * std::sin(t),
                                                         options.amplitude.y * std::sin(2 * t));
    pose.rotation = options.start.rotation + options.rotation_amplitude * std::sin(t);
    pose.scale = options.start.scale * (1.0 + options.scale_amplitude * std::sin(1.5 * t));
    poses.push_back(pose);
  }
  return poses;
}

std::vector<Pose> linear_motion_path(const Pose& start, const Point& shift, int frames) {
  if (frames < 0) throw std::invalid_argument("frames must be >= 0, got " + std::to_string(frames));
  std::vector<Pose> poses;
  poses.reserve(frames);
  for (int k = 0; k < frames; ++k) {
    Pose pose = start;
    pose.translation += shift * static_cast<double>(k);
    poses.push_back(pose);
  }
  return poses;
}

std::vector<Point> sample_boundary(const Polygon& polygon, double step) {
  if (!(step > 0.0)) throw std::invalid_argument("step must be positive, got " + number(step));
  std::vector<Point> samples;
  const size_t n = polygon.size();
  for (size_t i = 0; i < n; ++i) {
    const Point& a = polygon[i];
    const Point& b = polygon[(i + 1) % n];
    const double length = std::hypot(b.x - a.x, b.y - a.y);
    const int pieces = std::max(1, static_cast<int>(std::ceil(length / step)));
    for (int k = 0; k < pieces; ++k) samples.push_back(a + (b - a) * (double(k) / pieces));
    if (n == 1) break;
  }
  return samples;
}

double mean_boundary_distance(const Polygon& a, const Polygon& b, double step) {
  if (a.size() < 2 || b.size() < 2) return std::numeric_limits<double>::infinity();
  auto one_way = [step](const Polygon& from, const Polygon& to) {
    const std::vector<Point> samples = sample_boundary(from, step);
    double sum = 0.0;
    for (const Point& p : samples) sum += distance_to_boundary(p, to);
    return sum / static_cast<double>(samples.size());
  };
  return 0.5 * (one_way(a, b) + one_way(b, a));
}

}  // namespace scbt
