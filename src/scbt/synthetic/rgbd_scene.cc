#include "scbt/synthetic/rgbd_scene.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <opencv2/core.hpp>
#include <stdexcept>

namespace scbt {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kNoHit = std::numeric_limits<double>::infinity();

enum class Surface { kNone, kTable, kLip, kBowlInside, kBowlOutside, kBoxTop, kBoxSide };

struct Hit {
  double t = kNoHit;  // along the object-frame ray
  Surface surface = Surface::kNone;
  Eigen::Vector3d normal{0, 0, 1};  // object frame
  Eigen::Vector3d point{0, 0, 0};   // object frame
};

// The object's frame: columns u, v (in the rim's plane, turned by pose.spin) and the normal.
Eigen::Matrix3d object_axes(const RimPose& pose) {
  const Eigen::Vector3d n = pose.normal.normalized();
  const Eigen::Vector3d helper =
      std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d u0 = helper.cross(n).normalized();
  const Eigen::Vector3d v0 = n.cross(u0);
  const Eigen::Vector3d u = std::cos(pose.spin) * u0 + std::sin(pose.spin) * v0;
  Eigen::Matrix3d axes;
  axes << u, n.cross(u), n;
  return axes;
}

void consider(Hit* best, double t, Surface surface, const Eigen::Vector3d& point,
              const Eigen::Vector3d& normal) {
  if (t > 1e-9 && t < best->t) *best = {t, surface, normal, point};
}

// The plane z = height of the object frame.
double plane_t(const Eigen::Vector3d& o, const Eigen::Vector3d& d, double height) {
  return std::abs(d.z()) < 1e-12 ? kNoHit : (height - o.z()) / d.z();
}

void intersect_bowl(const RgbdSceneOptions& s, const Eigen::Vector3d& o, const Eigen::Vector3d& d,
                    Hit* best) {
  const double inner = s.rim_radius - s.lip_width;
  const double t_rim = plane_t(o, d, 0.0);
  if (t_rim < kNoHit) {
    const Eigen::Vector3d p = o + t_rim * d;
    const double r = std::hypot(p.x(), p.y());
    // Shaded with the inside's normal where they meet: a rounded rim shows no shading step.
    const double h = s.bowl_depth, rho = (inner * inner + h * h) / (2.0 * h);
    const Eigen::Vector3d rounded = (Eigen::Vector3d(0, 0, rho - h) - p).normalized();
    if (r >= inner && r <= s.rim_radius) consider(best, t_rim, Surface::kLip, p, rounded);
  }
  // A thin spherical shell through the lip's inner edge, its bottom bowl_depth below the rim.
  const double h = s.bowl_depth;
  const double rho = (inner * inner + h * h) / (2.0 * h);
  const Eigen::Vector3d centre(0, 0, rho - h);
  const Eigen::Vector3d oc = o - centre;
  const double b = oc.dot(d), c = oc.squaredNorm() - rho * rho, a = d.squaredNorm();
  const double discriminant = b * b - a * c;
  if (discriminant < 0.0) return;
  const double root = std::sqrt(discriminant);
  const double entry = (-b - root) / a, exit = (-b + root) / a;
  const Eigen::Vector3d p_entry = o + entry * d, p_exit = o + exit * d;
  if (p_entry.z() < 0.0)
    consider(best, entry, Surface::kBowlOutside, p_entry, (p_entry - centre).normalized());
  else if (p_exit.z() < 0.0)
    consider(best, exit, Surface::kBowlInside, p_exit, (centre - p_exit).normalized());
}

void intersect_box(const RgbdSceneOptions& s, const Eigen::Vector3d& o, const Eigen::Vector3d& d,
                   Hit* best) {
  const Eigen::Vector3d lo(-0.5 * s.box_length, -0.5 * s.box_width, -s.box_height);
  const Eigen::Vector3d hi(0.5 * s.box_length, 0.5 * s.box_width, 0.0);
  double t_near = -kNoHit, t_far = kNoHit;
  int axis_near = 2;
  for (int axis = 0; axis < 3; ++axis) {
    if (std::abs(d[axis]) < 1e-12) {
      if (o[axis] < lo[axis] || o[axis] > hi[axis]) return;
      continue;
    }
    double t0 = (lo[axis] - o[axis]) / d[axis], t1 = (hi[axis] - o[axis]) / d[axis];
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > t_near) t_near = t0, axis_near = axis;
    t_far = std::min(t_far, t1);
  }
  if (t_near > t_far || t_near <= 0.0) return;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  normal[axis_near] = d[axis_near] < 0.0 ? 1.0 : -1.0;
  const bool top = axis_near == 2 && normal.z() > 0.0;
  consider(best, t_near, top ? Surface::kBoxTop : Surface::kBoxSide, o + t_near * d, normal);
}

double table_height(const RgbdSceneOptions& s) {
  return s.shape == RimShape::kBowl ? -s.bowl_depth : -s.box_height;
}

Hit cast(const RgbdSceneOptions& s, const Eigen::Vector3d& o, const Eigen::Vector3d& d) {
  Hit best;
  const double t_table = plane_t(o, d, table_height(s));
  if (t_table < kNoHit) consider(&best, t_table, Surface::kTable, o + t_table * d, {0, 0, 1});
  if (s.shape == RimShape::kBowl)
    intersect_bowl(s, o, d, &best);
  else
    intersect_box(s, o, d, &best);
  return best;
}

// Grey level of a hit: a flat albedo per material (a wavy wood-like texture on the table), lit
// from above-front.
double shade(const Hit& hit, const Eigen::Matrix3d& axes) {
  static const Eigen::Vector3d light = Eigen::Vector3d(0.2, -0.7, -0.7).normalized();
  double albedo = 0.0;
  switch (hit.surface) {
    case Surface::kNone:
      return 40.0;
    case Surface::kTable:
      albedo = 95.0 + 14.0 * std::sin(60.0 * hit.point.x() + 4.0 * std::sin(9.0 * hit.point.y()));
      break;
    case Surface::kLip:  // one glazed material: lip and inside differ only by their shading
    case Surface::kBowlInside:
    case Surface::kBowlOutside:
      albedo = 225.0;
      break;
    case Surface::kBoxTop:
      albedo = 235.0;
      break;
    case Surface::kBoxSide:
      albedo = 160.0;
      break;
  }
  const double lit = std::abs((axes * hit.normal).dot(light));
  return albedo * (0.55 + 0.45 * lit);
}

Polygon project_all(const PinholeIntrinsics& camera, const std::vector<Eigen::Vector3d>& points) {
  Polygon polygon;
  for (const Eigen::Vector3d& p : points) polygon.push_back(project_point(camera, p));
  return polygon;
}

std::vector<Eigen::Vector3d> rim_points(const RgbdSceneOptions& s, const Eigen::Matrix3d& axes,
                                        const Eigen::Vector3d& centre) {
  std::vector<Eigen::Vector3d> rim;
  if (s.shape == RimShape::kBowl) {
    for (int i = 0; i < s.rim_vertices; ++i) {
      const double angle = 2.0 * kPi * i / s.rim_vertices;
      rim.push_back(centre + axes * Eigen::Vector3d(s.rim_radius * std::cos(angle),
                                                    s.rim_radius * std::sin(angle), 0.0));
    }
    return rim;
  }
  const double a = 0.5 * s.box_length, b = 0.5 * s.box_width;
  const Eigen::Vector3d corners[4] = {{-a, -b, 0}, {a, -b, 0}, {a, b, 0}, {-a, b, 0}};
  for (int k = 0; k < 4; ++k)
    for (int piece = 0; piece < s.box_edge_pieces; ++piece) {
      const double f = static_cast<double>(piece) / s.box_edge_pieces;
      rim.push_back(centre + axes * ((1.0 - f) * corners[k] + f * corners[(k + 1) % 4]));
    }
  return rim;
}

}  // namespace

RimShape parse_rim_shape(const std::string& name) {
  if (name == "bowl") return RimShape::kBowl;
  if (name == "box") return RimShape::kBox;
  throw std::invalid_argument("unknown rim shape '" + name + "' (bowl or box)");
}

void RgbdSceneOptions::check() const {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument("RGB-D scene options: " + what);
  };
  require(size.width >= 16 && size.height >= 16, "size must be at least 16x16");
  camera.check();
  require(rim_radius > 0.0 && lip_width > 0.0 && lip_width < rim_radius,
          "need 0 < lip_width < rim_radius");
  require(bowl_depth > 0.0, "bowl_depth must be positive");
  require(box_length > 0.0 && box_width > 0.0 && box_height > 0.0, "box sizes must be positive");
  require(rim_vertices >= 8, "rim_vertices must be >= 8");
  require(box_edge_pieces >= 1, "box_edge_pieces must be >= 1");
  require(image_noise_sigma >= 0.0, "image_noise_sigma must be >= 0");
}

RgbdFrame render_rgbd_frame(const RgbdSceneOptions& options, const RimPose& pose, int frame_index) {
  options.check();
  const Eigen::Matrix3d axes = object_axes(pose);
  const Eigen::Vector3d origin = -(axes.transpose() * pose.centre);  // camera in object frame
  RgbdFrame frame;
  frame.colour.create(options.size, CV_8UC3);
  frame.clean_depth.create(options.size, CV_32FC1);
  cv::Mat grey(options.size, CV_32FC1);
  cv::Mat surface(options.size, CV_8UC1);
  auto hit_at = [&](double x, double y) {
    return cast(options, origin, axes.transpose() * pixel_ray(options.camera, Point(x, y)));
  };
  for (int y = 0; y < options.size.height; ++y)
    for (int x = 0; x < options.size.width; ++x) {
      const Hit hit = hit_at(x, y);  // t is the depth: the ray has z = 1
      frame.clean_depth.at<float>(y, x) =
          hit.surface == Surface::kNone ? 0.0f : static_cast<float>(hit.t);
      grey.at<float>(y, x) = static_cast<float>(shade(hit, axes));
      surface.at<std::uint8_t>(y, x) = static_cast<std::uint8_t>(hit.surface);
    }
  // Anti-aliasing: pixels next to another surface are the mean of 2x2 sub-pixel rays.
  static const double kSub[4][2] = {{-0.25, -0.25}, {0.25, -0.25}, {-0.25, 0.25}, {0.25, 0.25}};
  const cv::Rect frame_rect(cv::Point(0, 0), options.size);
  cv::Mat smooth = grey.clone();
  for (int y = 0; y < options.size.height; ++y)
    for (int x = 0; x < options.size.width; ++x) {
      const std::uint8_t own = surface.at<std::uint8_t>(y, x);
      bool border = false;
      for (int dy = -1; dy <= 1 && !border; ++dy)
        for (int dx = -1; dx <= 1 && !border; ++dx)
          border = frame_rect.contains(cv::Point(x + dx, y + dy)) &&
                   surface.at<std::uint8_t>(y + dy, x + dx) != own;
      if (!border) continue;
      double sum = 0.0;
      for (const auto& offset : kSub) sum += shade(hit_at(x + offset[0], y + offset[1]), axes);
      smooth.at<float>(y, x) = static_cast<float>(sum / 4.0);
    }
  grey = smooth;
  cv::RNG rng(options.seed * 7919u + static_cast<unsigned>(frame_index) * 104729u + 17u);
  cv::Mat noise(options.size, CV_32FC1);
  rng.fill(noise, cv::RNG::NORMAL, 0.0, options.image_noise_sigma);
  grey += noise;
  cv::Mat grey8;
  grey.convertTo(grey8, CV_8U);
  cv::merge(std::vector<cv::Mat>{grey8 * 0.9, grey8, grey8}, frame.colour);
  frame.clean_depth.convertTo(frame.depth, CV_16U, 1000.0);
  frame.truth_rim = rim_points(options, axes, pose.centre);
  frame.truth = project_all(options.camera, frame.truth_rim);
  frame.centre = pose.centre;
  frame.normal = axes.col(2);
  frame.radius = options.shape == RimShape::kBowl ? options.rim_radius : 0.0;
  return frame;
}

void RimPathOptions::check() const {
  if (!(start.allFinite() && end.allFinite() && start.z() > 0.0 && end.z() > 0.0))
    throw std::invalid_argument("rim path: start and end must be finite with z > 0");
  if (!(sway >= 0.0 && tilt_min >= 0.0 && tilt_max >= tilt_min && tilt_max < 1.5 && spin >= 0.0))
    throw std::invalid_argument("rim path: need sway >= 0, 0 <= tilt_min <= tilt_max < 1.5");
}

std::vector<RimPose> rim_path(const RimPathOptions& options, int frames) {
  options.check();
  std::vector<RimPose> poses;
  for (int i = 0; i < frames; ++i) {
    const double f = frames > 1 ? static_cast<double>(i) / (frames - 1) : 0.0;
    RimPose pose;
    pose.centre =
        options.start + f * (options.end - options.start) +
        options.sway * Eigen::Vector3d(std::sin(2.0 * kPi * f), 0.5 * std::sin(4.0 * kPi * f), 0.0);
    // Tilt: the normal leans from the direction to the camera towards the image's up (-y),
    // as a bowl on a table seen from above-front.
    const double tilt = options.tilt_min + (options.tilt_max - options.tilt_min) * 0.5 *
                                               (1.0 - std::cos(2.0 * kPi * f));
    const Eigen::Vector3d towards_camera = -pose.centre.normalized();
    const Eigen::Vector3d up =
        (Eigen::Vector3d(0, -1, 0) - Eigen::Vector3d(0, -1, 0).dot(towards_camera) * towards_camera)
            .normalized();
    pose.normal = std::cos(tilt) * towards_camera + std::sin(tilt) * up;
    pose.spin = options.spin * std::sin(2.0 * kPi * f);
    poses.push_back(pose);
  }
  return poses;
}

}  // namespace scbt
