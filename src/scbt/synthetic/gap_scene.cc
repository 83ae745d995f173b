#include "scbt/synthetic/gap_scene.h"

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <random>
#include <stdexcept>

namespace scbt {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Frames an occluder takes to slide over the whole object, and an exit to leave the frame.
constexpr int kCoverFrames = 4;
// The grey level of blank frames.
constexpr int kBlankLevel = 128;

// The occluder: a flat rectangle of its own grey level (far from the object's) with sensor noise.
void draw_occluder(const cv::Rect& rect, int level, double noise_sigma, int frame_index,
                   cv::Mat* image) {
  const cv::Rect inside = rect & cv::Rect(cv::Point(0, 0), image->size());
  if (inside.empty()) return;
  cv::Mat grey(inside.size(), CV_32F, cv::Scalar(level));
  cv::RNG rng(0x0CC1 + frame_index);
  cv::Mat noise(inside.size(), CV_32F);
  rng.fill(noise, cv::RNG::NORMAL, 0.0, noise_sigma);
  grey += noise;
  cv::Mat patch;
  grey.convertTo(patch, CV_8U);
  cv::cvtColor(patch, (*image)(inside), cv::COLOR_GRAY2BGR);
}

}  // namespace

GapKind parse_gap_kind(const std::string& name) {
  if (name == "occluder") return GapKind::kOccluder;
  if (name == "exit") return GapKind::kExit;
  if (name == "blank") return GapKind::kBlank;
  throw std::invalid_argument("unknown gap kind \"" + name +
                              "\" (expected occluder, exit or blank)");
}

std::string to_string(GapKind kind) {
  switch (kind) {
    case GapKind::kOccluder:
      return "occluder";
    case GapKind::kExit:
      return "exit";
    case GapKind::kBlank:
      return "blank";
  }
  return "unknown";
}

void GapSceneOptions::check() const {
  if (frames_before < 2 || frames_before > 10000 || frames_after < 1 || frames_after > 10000) {
    throw std::invalid_argument("frames_before must be in 2..10000 and frames_after in 1..10000");
  }
  if (gap < 1 || gap > 10000) {
    throw std::invalid_argument("gap must be in 1..10000, got " + std::to_string(gap));
  }
  if (!(drift >= 0.0 && drift <= 10.0)) {
    throw std::invalid_argument("drift must be in [0, 10] px per frame, got " +
                                std::to_string(drift));
  }
}

GapScene render_gap_scene(const SceneOptions& scene, const GapSceneOptions& options) {
  scene.check();
  options.check();
  std::mt19937 rng(scene.seed * 2654435761u + static_cast<unsigned>(options.kind));
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Polygon model = object_model(scene);
  const double radius = scene.object_size;
  const double w = scene.size.width, h = scene.size.height;

  // Phases: before, going (partly hidden), gone, coming (partly hidden), after.
  const bool gradual = options.kind != GapKind::kBlank;
  const int going = gradual ? kCoverFrames : 0;
  const int coming = options.kind == GapKind::kOccluder ? kCoverFrames : 0;
  const int total = options.frames_before + going + options.gap + coming + options.frames_after;

  // The object's poses: a slow drift; an exit leaves through the right edge at speed and comes
  // back, whole, somewhere in the left half.
  const double direction = 2.0 * kPi * unit(rng);
  const Point drift = Point(std::cos(direction), std::sin(direction)) * options.drift;
  Pose start;
  start.rotation = 2.0 * kPi * unit(rng);
  start.translation = Point(w * (0.35 + 0.3 * unit(rng)), h * (0.4 + 0.2 * unit(rng)));
  Pose back = start;
  back.translation = Point(radius * 1.3 + (0.5 * w - 2.6 * radius) * unit(rng),
                           radius * 1.3 + (h - 2.6 * radius) * unit(rng));
  std::vector<Pose> poses(total, start);
  const int first_going = options.frames_before;
  const int first_gone = first_going + going;
  const int first_coming = first_gone + options.gap;
  const int first_after = first_coming + coming;
  for (int k = 0; k < total; ++k) poses[k].translation = start.translation + drift * k;
  if (options.kind == GapKind::kExit) {
    const Point at_exit = poses[first_going].translation;
    const double speed = (w + radius * 1.5 - at_exit.x) / kCoverFrames;
    for (int k = first_going; k < first_coming; ++k) {
      poses[k].translation = at_exit + Point(speed * (k - first_going + 1), 0.0);
    }
    for (int k = first_coming; k < total; ++k) {
      poses[k].translation = back.translation + drift * (k - first_coming);
    }
  }

  GapScene out;
  out.first_back = first_after;
  // Background clutter around where the object is seen.
  std::vector<Pose> seen;
  for (int k = 0; k < total; ++k) {
    if (k < first_going || k >= first_after) seen.push_back(poses[k]);
  }
  const cv::Mat background = render_background(scene, path_region(model, seen));
  const int occluder_level =
      scene.object_level > 128 ? scene.object_level - 120 : scene.object_level + 120;
  // The occluder slides over the object (width 2.4 radius) in kCoverFrames, covers it wholly for
  // `gap` frames and slides off in kCoverFrames, following the object's drift.
  const double extent = 2.4 * radius;
  const double cover_speed = extent / kCoverFrames;
  const double occluder_width = extent + cover_speed * options.gap;
  for (int k = 0; k < total; ++k) {
    SceneFrame frame = render_frame(scene, background, model, poses[k], k);
    const bool gone = k >= first_gone && k < first_coming;
    const bool partly =
        (k >= first_going && k < first_gone) || (k >= first_coming && k < first_after);
    if (options.kind == GapKind::kBlank && gone) {
      frame.image.setTo(cv::Scalar::all(kBlankLevel));
    }
    if (options.kind == GapKind::kOccluder && (gone || partly)) {
      const Point centre = poses[k].translation;
      const double right = centre.x - 0.5 * extent + cover_speed * (k - first_going + 1);
      draw_occluder(cv::Rect(cvRound(right - occluder_width), cvRound(centre.y - 0.75 * extent),
                             cvRound(occluder_width), cvRound(1.5 * extent)),
                    occluder_level, scene.noise_sigma, k, &frame.image);
    }
    out.hidden.push_back(gone);
    out.partly_hidden.push_back(partly);
    out.frames.push_back(std::move(frame));
  }
  return out;
}

}  // namespace scbt
