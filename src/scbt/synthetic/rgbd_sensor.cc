#include "scbt/synthetic/rgbd_sensor.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

namespace scbt {
namespace {

// Each depth-edge pixel (a 4-neighbour more than edge_jump away), with probability
// mixed_pixel_share, reads a random blend of its own depth and that neighbour's; with
// mixed_pixel_band > 1 the rings behind it (on its own side of the edge) blend, less, with the
// same far side.
void add_mixed_pixels(const cv::Mat& clean, const DepthSensorOptions& options, cv::RNG& rng,
                      cv::Mat* depth) {
  static const int kNeighbours[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  cv::Mat across(clean.size(), CV_32FC1, cv::Scalar(0.0f));  // the edge's other side, 0 = none
  auto mix = [&](int y, int x, float z, float other, int ring) {
    if (rng.uniform(0.0, 1.0) >= options.mixed_pixel_share) return;
    const double w = rng.uniform(options.mixed_weight_min, options.mixed_weight_max) / ring;
    depth->at<float>(y, x) = static_cast<float>(z + w * (other - z));
  };
  for (int y = 1; y + 1 < clean.rows; ++y)
    for (int x = 1; x + 1 < clean.cols; ++x) {
      const float z = clean.at<float>(y, x);
      float other = z;
      for (const auto& n : kNeighbours) {
        const float candidate = clean.at<float>(y + n[1], x + n[0]);
        if (std::abs(candidate - z) > std::abs(other - z)) other = candidate;
      }
      if (std::abs(other - z) <= options.edge_jump || z <= 0.0f || other <= 0.0f) continue;
      across.at<float>(y, x) = other;
      mix(y, x, z, other, 1);
    }
  for (int ring = 2; ring <= options.mixed_pixel_band; ++ring) {
    const cv::Mat previous = across.clone();
    for (int y = 1; y + 1 < clean.rows; ++y)
      for (int x = 1; x + 1 < clean.cols; ++x) {
        const float z = clean.at<float>(y, x);
        if (previous.at<float>(y, x) > 0.0f || z <= 0.0f) continue;
        for (const auto& n : kNeighbours) {
          const float other = previous.at<float>(y + n[1], x + n[0]);
          const float neighbour = clean.at<float>(y + n[1], x + n[0]);
          if (other <= 0.0f || std::abs(neighbour - z) > options.edge_jump) continue;
          across.at<float>(y, x) = other;
          mix(y, x, z, other, ring);
          break;
        }
      }
  }
}

// Elliptic blobs (semi-axes 3-12 px) at random places until `share` of the image is covered.
void add_hole_share(double share, cv::RNG& rng, cv::Mat* mask) {
  const double wanted = share * static_cast<double>(mask->total());
  for (int tries = 0; tries < 100000 && cv::countNonZero(*mask) < wanted; ++tries) {
    for (int i = 0; i < 16; ++i) {
      const cv::Point centre(rng.uniform(0, mask->cols), rng.uniform(0, mask->rows));
      const cv::Size axes(rng.uniform(3, 13), rng.uniform(3, 13));
      cv::ellipse(*mask, centre, axes, rng.uniform(0.0, 180.0), 0, 360, cv::Scalar(255), -1);
    }
  }
}

// Arcs of the outline, together outline_missing_share of its length, drawn as thick lines.
void drop_outline_depth(const Polygon& outline, const DepthSensorOptions& options, cv::RNG& rng,
                        cv::Mat* mask) {
  const std::size_t n = outline.size();
  if (n < 2 || options.outline_missing_share <= 0.0) return;
  std::vector<double> cumulative(n + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const Point d = outline[(i + 1) % n] - outline[i];
    cumulative[i + 1] = cumulative[i] + std::hypot(d.x, d.y);
  }
  const double perimeter = cumulative[n];
  auto point_at = [&](double s) {
    s = std::fmod(std::fmod(s, perimeter) + perimeter, perimeter);
    const std::size_t i =
        std::upper_bound(cumulative.begin(), cumulative.end(), s) - cumulative.begin() - 1;
    const double length = cumulative[i + 1] - cumulative[i];
    const double f = length > 0.0 ? (s - cumulative[i]) / length : 0.0;
    return outline[i] + (outline[(i + 1) % n] - outline[i]) * f;
  };
  // The thick line's round caps lose outline_missing_width more at each end of an arc.
  const double share = options.outline_missing_share * perimeter / options.outline_missing_pieces;
  const double arc = std::max(1.0, share - 2.0 * options.outline_missing_width);
  const double first = rng.uniform(0.0, perimeter);
  const int thickness = static_cast<int>(std::lround(2.0 * options.outline_missing_width)) + 1;
  for (int piece = 0; piece < options.outline_missing_pieces; ++piece) {
    // Evenly spread starts, jittered, so the arcs do not overlap.
    const double start =
        first + perimeter * piece / options.outline_missing_pieces +
        rng.uniform(0.0, 0.5) * (perimeter / options.outline_missing_pieces - share);
    for (double s = start; s < start + arc; s += 1.0) {
      const Point a = point_at(s), b = point_at(std::min(s + 1.0, start + arc));
      cv::line(*mask, cv::Point(cvRound(a.x), cvRound(a.y)), cv::Point(cvRound(b.x), cvRound(b.y)),
               cv::Scalar(255), thickness);
    }
  }
}

}  // namespace

void DepthSensorOptions::check() const {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument("depth sensor options: " + what);
  };
  require(depth_scale > 0.0, "depth_scale must be positive");
  require(noise_at_1m >= 0.0, "noise_at_1m must be >= 0");
  require(edge_jump > 0.0, "edge_jump must be positive");
  require(mixed_pixel_share >= 0.0 && mixed_pixel_share <= 1.0, "mixed_pixel_share in [0, 1]");
  require(
      mixed_weight_min >= 0.0 && mixed_weight_min <= mixed_weight_max && mixed_weight_max <= 1.0,
      "need 0 <= mixed_weight_min <= mixed_weight_max <= 1");
  require(mixed_pixel_band >= 1 && mixed_pixel_band <= 8, "mixed_pixel_band in [1, 8]");
  require(hole_blobs >= 0, "hole_blobs must be >= 0");
  require(hole_share >= 0.0 && hole_share < 0.9, "hole_share in [0, 0.9)");
  require(outline_missing_share >= 0.0 && outline_missing_share < 1.0,
          "outline_missing_share in [0, 1)");
  require(outline_missing_pieces >= 1, "outline_missing_pieces must be >= 1");
  require(outline_missing_width >= 0.0, "outline_missing_width must be >= 0");
}

DepthSensorOptions edge_artefact_sensor(std::uint32_t seed) {
  DepthSensorOptions options;
  options.noise_at_1m = 0.0015;
  options.mixed_pixel_share = 1.0;
  options.mixed_weight_min = 0.0;
  options.mixed_weight_max = 0.5;
  options.mixed_pixel_band = 2;
  options.hole_share = 0.10;
  options.seed = seed;
  return options;
}

cv::Mat apply_depth_sensor(const cv::Mat& clean_depth, const Polygon& outline,
                           const DepthSensorOptions& options, int frame_index) {
  options.check();
  if (clean_depth.type() != CV_32FC1) throw std::invalid_argument("clean depth must be CV_32FC1");
  cv::RNG rng(options.seed * 2654435761u + static_cast<unsigned>(frame_index) * 40503u + 3u);
  cv::Mat depth = clean_depth.clone();
  add_mixed_pixels(clean_depth, options, rng, &depth);
  for (int y = 0; y < depth.rows; ++y) {
    float* row = depth.ptr<float>(y);
    for (int x = 0; x < depth.cols; ++x)
      if (row[x] > 0.0f)
        row[x] += static_cast<float>(rng.gaussian(options.noise_at_1m * row[x] * row[x]));
  }
  cv::Mat holes = cv::Mat::zeros(depth.size(), CV_8UC1);
  for (int i = 0; i < options.hole_blobs; ++i) {
    const cv::Point centre(rng.uniform(0, depth.cols), rng.uniform(0, depth.rows));
    const cv::Size axes(rng.uniform(3, 16), rng.uniform(3, 16));
    cv::ellipse(holes, centre, axes, rng.uniform(0.0, 180.0), 0, 360, cv::Scalar(255), -1);
  }
  // Counted before the outline's lost arcs, which come on top.
  if (options.hole_share > 0.0) add_hole_share(options.hole_share, rng, &holes);
  drop_outline_depth(outline, options, rng, &holes);
  depth.setTo(cv::Scalar(0.0f), holes);
  cv::Mat units;
  depth.convertTo(units, CV_16U, 1.0 / options.depth_scale);  // rounds and saturates
  return units;
}

}  // namespace scbt
