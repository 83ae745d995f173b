#include "scbt/tracker/reacquire.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace scbt {
namespace {

constexpr int kOutlineSamples = 64;

// Points every perimeter / kOutlineSamples along the closed outline, relative to `center`.
std::vector<Point> outline_samples(const Polygon& outline, const Point& center) {
  std::vector<Point> samples;
  const size_t n = outline.size();
  const double step = perimeter(outline) / kOutlineSamples;
  size_t edge = 0;
  double edge_start = 0.0;
  double edge_length = cv::norm(outline[1 % n] - outline[0]);
  for (int i = 0; i < kOutlineSamples; ++i) {
    const double s = i * step;
    while (s > edge_start + edge_length && edge + 1 < n) {
      edge_start += edge_length;
      ++edge;
      edge_length = cv::norm(outline[(edge + 1) % n] - outline[edge]);
    }
    const double t = edge_length > 0.0 ? std::min(1.0, (s - edge_start) / edge_length) : 0.0;
    samples.push_back(outline[edge] + t * (outline[(edge + 1) % n] - outline[edge]) - center);
  }
  return samples;
}

struct Scored {
  double chamfer;
  Point center;
  double scale;
};

}  // namespace

Polygon foreshortened(const Polygon& outline, double factor) {
  std::vector<cv::Point2f> contour;
  for (const Point& p : outline) contour.emplace_back(p);
  const cv::Moments m = cv::moments(contour);
  if (!(std::abs(m.m00) > 0.0)) return outline;
  const Point center(m.m10 / m.m00, m.m01 / m.m00);
  // The minor axis is perpendicular to the major one, at 0.5 atan2(2 mu11, mu20 - mu02).
  const double angle = 0.5 * std::atan2(2.0 * m.mu11, m.mu20 - m.mu02);
  const Point minor(-std::sin(angle), std::cos(angle));
  Polygon out;
  out.reserve(outline.size());
  for (const Point& p : outline) {
    const Point d = p - center;
    out.push_back(p + (factor - 1.0) * d.dot(minor) * minor);
  }
  return out;
}

void Reacquirer::set_segments(const std::vector<Segment>& segments, cv::Size frame_size,
                              double cap) {
  empty_ = segments.empty();
  cap_ = cap;
  edges_.create(frame_size, CV_8U);
  edges_.setTo(255);
  for (const Segment& s : segments) {
    cv::line(edges_, cv::Point(cvRound(s.a.x), cvRound(s.a.y)),
             cv::Point(cvRound(s.b.x), cvRound(s.b.y)), 0);
  }
  cv::distanceTransform(edges_, distance_, cv::DIST_L2, 3, CV_32F);
  cv::min(distance_, cap, distance_);
}

std::vector<Placement> Reacquirer::rank(const Polygon& outline,
                                        const PlacementOptions& options) const {
  std::vector<Placement> placements;
  std::vector<Point> picked_centers;
  std::vector<double> picked_scales;
  const double size = std::sqrt(area(outline));
  if (empty_ || outline.size() < 3 || !(size > 0.0)) return placements;
  const cv::Size frame_size = distance_.size();

  const Point home = centroid(outline);
  const std::vector<Point> samples = outline_samples(outline, home);
  const int grid = std::clamp(static_cast<int>(size / 12.0), 2, 8);
  const double max_chamfer = options.max_chamfer_share * cap_;
  const int w = frame_size.width, h = frame_size.height;

  std::vector<Scored> scored;
  const double step = options.scale_step;
  // Only near placements wanted: only the grid within reach of them is scored.
  const bool near_only = options.frame_tries == 0;
  for (double scale = options.min_scale; scale <= options.max_scale * 1.0001; scale *= step) {
    double min_x = 0, max_x = 0, min_y = 0, max_y = 0;
    for (const Point& p : samples) {
      min_x = std::min(min_x, scale * p.x), max_x = std::max(max_x, scale * p.x);
      min_y = std::min(min_y, scale * p.y), max_y = std::max(max_y, scale * p.y);
    }
    // Centres from which up to (1 - min_inside_share) of the outline's extent leaves the frame.
    const double spill = 1.0 - options.min_inside_share;
    double x0 = -min_x * options.min_inside_share, x1 = w - 1 - max_x * options.min_inside_share;
    double y0 = -min_y * options.min_inside_share, y1 = h - 1 - max_y * options.min_inside_share;
    if (near_only) {
      x0 = std::max(x0, home.x - size), x1 = std::min(x1, home.x + size);
      y0 = std::max(y0, home.y - size), y1 = std::min(y1, home.y + size);
    }
    const int max_outside = static_cast<int>(spill * kOutlineSamples);
    for (double cy = y0; cy <= y1; cy += grid) {
      for (double cx = x0; cx <= x1; cx += grid) {
        double sum = 0.0;
        int outside = 0;
        for (const Point& p : samples) {
          const int x = cvRound(cx + scale * p.x), y = cvRound(cy + scale * p.y);
          if (x < 0 || y < 0 || x >= w || y >= h) {
            ++outside;
            sum += cap_;
          } else {
            sum += distance_.at<float>(y, x);
          }
        }
        const double chamfer = sum / kOutlineSamples;
        if (outside <= max_outside && chamfer <= max_chamfer) {
          scored.push_back({chamfer, Point(cx, cy), scale});
        }
      }
    }
  }
  std::sort(scored.begin(), scored.end(),
            [](const Scored& a, const Scored& b) { return a.chamfer < b.chamfer; });

  // Greedy picks, best first, apart from the ones already picked: a placement a quarter of the
  // object's size away, or a scale step away, is another hypothesis (a wider exclusion lets a
  // look-alike part of the clutter next to the object hide the object itself).
  const double separation = 0.25 * size;
  auto pick = [&](bool near, int count) {
    for (const Scored& s : scored) {
      if (count <= 0) return;
      const bool is_near = cv::norm(s.center - home) <= size;
      if (near && !is_near) continue;
      bool apart = true;
      for (size_t i = 0; i < placements.size() && apart; ++i) {
        const double ratio =
            std::max(s.scale, picked_scales[i]) / std::min(s.scale, picked_scales[i]);
        apart =
            cv::norm(picked_centers[i] - s.center) >= separation * s.scale || ratio > step * 1.0001;
      }
      if (!apart) continue;
      Placement placement;
      placement.chamfer = s.chamfer;
      placement.near = is_near;
      placement.scale = s.scale;
      for (const Point& v : outline) placement.outline.push_back(s.center + (v - home) * s.scale);
      placements.push_back(std::move(placement));
      picked_centers.push_back(s.center);
      picked_scales.push_back(s.scale);
      --count;
    }
  };
  pick(true, options.near_tries);
  pick(false, options.frame_tries);
  return placements;
}

}  // namespace scbt
