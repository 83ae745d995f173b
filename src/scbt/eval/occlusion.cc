#include "scbt/eval/occlusion.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "scbt/eval/spec_text.h"

namespace scbt {
namespace {

constexpr double kFps = 30.0;
constexpr int kFirstEventFrom = 15;  // frames before the first event can start
constexpr int kFirstEventSpread = 60;
constexpr int kClearMin = 60;  // frames in plain view between events: 2-5 s
constexpr int kClearSpread = 90;
constexpr int kAfterLastEvent = 30;  // frames after the last event, to see tracking come back
constexpr int kTextureTile = 64;
// An arm reaching in (stay) or a bar crossing (sweep) extends this far beyond the object.
constexpr double kFar = 4000.0;

const char kGrammar[] =
    "expected occlude:COVER[,SECONDS[,SHAPE[,MOTION[,FILL]]]] with COVER in 0.05..0.8, SECONDS in "
    "0.1..10, SHAPE bar|disc|hand, MOTION sweep|stay, FILL solid|textured";

const char* shape_name(OccluderShape s) {
  switch (s) {
    case OccluderShape::kBar:
      return "bar";
    case OccluderShape::kDisc:
      return "disc";
    case OccluderShape::kHand:
      return "hand";
  }
  return "?";
}

bool usable(const Polygon& p) { return p.size() >= 3 && area(p) > 4.0; }

// The object's frame for placing the occluder: its centre and half-extents along u and across.
struct ObjectFrame {
  Point centre;
  Point u, v;
  double along = 0.0;   // half-extent along u
  double across = 0.0;  // half-extent along v
};

ObjectFrame object_frame(const Polygon& truth, double direction) {
  ObjectFrame f;
  f.u = Point(std::cos(direction), std::sin(direction));
  f.v = Point(-f.u.y, f.u.x);
  const cv::Rect2d box = bounding_box(truth);
  f.centre = Point(box.x + box.width / 2, box.y + box.height / 2);
  for (const Point& p : truth) {
    f.along = std::max(f.along, std::abs((p - f.centre).dot(f.u)));
    f.across = std::max(f.across, std::abs((p - f.centre).dot(f.v)));
  }
  return f;
}

// A rectangle from a to b (its axis) of half-width h.
Polygon capsule_box(Point a, Point b, double h) {
  Point d = b - a;
  const double n = std::max(1e-9, std::hypot(d.x, d.y));
  const Point side(-d.y / n * h, d.x / n * h);
  return {a + side, b + side, b - side, a - side};
}

Polygon ellipse(Point centre, Point u, double a, double b, int n = 32) {
  const Point v(-u.y, u.x);
  Polygon out;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * CV_PI * k / n;
    out.push_back(centre + u * (a * std::cos(t)) + v * (b * std::sin(t)));
  }
  return out;
}

// The occluder's extent along u on its leading side (from its reference point), so that a sweep
// starts and ends just off the object.
double reach(OccluderShape shape, double size) {
  switch (shape) {
    case OccluderShape::kBar:
      return size / 2;
    case OccluderShape::kDisc:
      return size;
    case OccluderShape::kHand:
      return 1.1 * size;
  }
  return size;
}

// Parts of an occluder whose reference point is `at`, moving along f.u. With `arm`, it reaches in
// from far away behind it (a hand or a tool held from outside the view).
std::vector<Polygon> parts_at(OccluderShape shape, double size, const ObjectFrame& f, Point at,
                              bool arm) {
  std::vector<Polygon> parts;
  switch (shape) {
    case OccluderShape::kBar:
      if (arm) {
        // Its tip at `at`, width `size`, coming in along u.
        parts.push_back(capsule_box(at - f.u * kFar, at, size / 2));
      } else {
        // Across the whole object, `size` wide along u.
        parts.push_back(
            capsule_box(at - f.v * (f.across + kFar), at + f.v * (f.across + kFar), size / 2));
      }
      break;
    case OccluderShape::kDisc:
      parts.push_back(ellipse(at, f.u, size, size));
      if (arm) parts.push_back(capsule_box(at - f.u * kFar, at, 0.35 * size));
      break;
    case OccluderShape::kHand: {
      // A palm with four fingers pointing along u and a thumb to one side.
      const Point palm = at - f.u * (0.45 * size);
      parts.push_back(ellipse(palm, f.u, 0.45 * size, 0.4 * size));
      for (int k = 0; k < 4; ++k) {
        const double off = (-0.27 + 0.18 * k) * size;
        const double len = (k == 0 || k == 3) ? 0.45 * size : 0.55 * size;
        const Point base = palm + f.v * off;
        parts.push_back(capsule_box(base, base + f.u * (0.45 * size + len), 0.075 * size));
      }
      const Point thumb = palm + f.v * (0.35 * size);
      parts.push_back(
          capsule_box(thumb, thumb + (f.u * 0.5 + f.v * 0.6) * (0.5 * size), 0.08 * size));
      if (arm) parts.push_back(capsule_box(palm - f.u * kFar, palm, 0.3 * size));
      break;
    }
  }
  return parts;
}

bool inside_any(const Point& p, const std::vector<std::vector<cv::Point2f>>& parts) {
  for (const auto& part : parts) {
    if (cv::pointPolygonTest(part, cv::Point2f(static_cast<float>(p.x), static_cast<float>(p.y)),
                             false) >= 0) {
      return true;
    }
  }
  return false;
}

// Sweep position t in [0, 1] -> offset along u; stay: in over the first quarter, still over the
// middle half, out over the last quarter.
double offset_at(const OcclusionEvent& e, OccluderMotion motion, double start_offset,
                 double end_offset, int index) {
  const double t = e.length <= 1 ? 0.5 : static_cast<double>(index - e.start) / (e.length - 1);
  if (motion == OccluderMotion::kSweep) return start_offset + t * (end_offset - start_offset);
  const double in = std::min(1.0, std::min(t, 1.0 - t) / 0.25);
  return start_offset + in * (e.stay_offset - start_offset);
}

}  // namespace

std::string OcclusionSpec::name() const {
  return format_spec_number(cover) + "," + format_spec_number(seconds) + "," + shape_name(shape) +
         "," + (motion == OccluderMotion::kSweep ? "sweep" : "stay") + "," +
         (textured ? "textured" : "solid");
}

void OcclusionSpec::check() const {
  if (!(cover >= 0.05 && cover <= 0.8)) {
    throw std::invalid_argument("occlusion " + name() + ": the cover must be in 0.05..0.8");
  }
  if (!(seconds >= 0.1 && seconds <= 10)) {
    throw std::invalid_argument("occlusion " + name() + ": the length must be in 0.1..10 s");
  }
}

OcclusionSpec parse_occlusion_spec(const std::string& text) {
  std::vector<std::string> fields;
  std::string field;
  for (size_t i = 0; i <= text.size(); ++i) {
    if (i == text.size() || text[i] == ',') {
      fields.push_back(field);
      field.clear();
    } else {
      field += text[i];
    }
  }
  if (fields.size() > 5) {
    throw std::invalid_argument("occlusion '" + text + "': too many fields; " + kGrammar);
  }
  OcclusionSpec spec;
  spec.cover = parse_spec_number(fields[0], "occlusion '" + text + "'", kGrammar);
  if (fields.size() > 1)
    spec.seconds = parse_spec_number(fields[1], "occlusion '" + text + "'", kGrammar);
  const auto bad = [&text](const std::string& f) {
    return std::invalid_argument("occlusion '" + text + "': unknown '" + f + "'; " + kGrammar);
  };
  if (fields.size() > 2) {
    if (fields[2] == "bar") {
      spec.shape = OccluderShape::kBar;
    } else if (fields[2] == "disc") {
      spec.shape = OccluderShape::kDisc;
    } else if (fields[2] == "hand") {
      spec.shape = OccluderShape::kHand;
    } else {
      throw bad(fields[2]);
    }
  }
  if (fields.size() > 3) {
    if (fields[3] == "sweep") {
      spec.motion = OccluderMotion::kSweep;
    } else if (fields[3] == "stay") {
      spec.motion = OccluderMotion::kStay;
    } else {
      throw bad(fields[3]);
    }
  }
  if (fields.size() > 4) {
    if (fields[4] == "solid") {
      spec.textured = false;
    } else if (fields[4] == "textured") {
      spec.textured = true;
    } else {
      throw bad(fields[4]);
    }
  }
  spec.check();
  return spec;
}

double hidden_outline_fraction(const Polygon& outline, const std::vector<Polygon>& parts) {
  std::vector<std::vector<cv::Point2f>> fparts;
  for (const Polygon& p : parts) {
    std::vector<cv::Point2f> f;
    for (const Point& q : p) f.emplace_back(static_cast<float>(q.x), static_cast<float>(q.y));
    fparts.push_back(std::move(f));
  }
  double hidden = 0.0, total = 0.0;
  for (size_t i = 0; i < outline.size(); ++i) {
    const Point a = outline[i];
    const Point b = outline[(i + 1) % outline.size()];
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    const int steps = std::max(1, static_cast<int>(std::ceil(len / 2.0)));
    for (int s = 0; s < steps; ++s) {
      const Point p = a + (b - a) * ((s + 0.5) / steps);
      total += len / steps;
      if (inside_any(p, fparts)) hidden += len / steps;
    }
  }
  return total > 0 ? hidden / total : 0.0;
}

OcclusionPlan::OcclusionPlan(const OcclusionSpec& spec, const std::vector<Polygon>& truth,
                             std::uint64_t seed)
    : spec_(spec), truth_(truth) {
  spec_.check();
  cv::RNG rng(mix_seed(seed ^ 0x6f63636c75646555ULL));
  const int length = std::max(1, static_cast<int>(std::lround(spec_.seconds * kFps)));
  const int n = static_cast<int>(truth_.size());
  int start = kFirstEventFrom + rng.uniform(0, kFirstEventSpread);
  while (start + length + kAfterLastEvent <= n) {
    OcclusionEvent e;
    e.start = start;
    e.length = length;
    e.direction = rng.uniform(0.0, 2 * CV_PI);
    e.colour = cv::Scalar(rng.uniform(0, 256), rng.uniform(0, 256), rng.uniform(0, 256));
    e.texture_seed = rng.next();
    const Polygon& at = truth_[start + length / 2];
    if (usable(at)) {
      e.scale = std::sqrt(area(at));
      const ObjectFrame f = object_frame(at, e.direction);
      const double extent = std::max(1.0, std::max(f.along, f.across));
      if (spec_.motion == OccluderMotion::kSweep) {
        // The size whose worst position over the sweep hides `cover` of the outline.
        const auto worst = [&](double size) {
          double most = 0.0;
          for (int k = 0; k <= 24; ++k) {
            const double off = (-1.0 + k / 12.0) * (f.along + reach(spec_.shape, size));
            most = std::max(most,
                            hidden_outline_fraction(
                                at, parts_at(spec_.shape, size, f, f.centre + f.u * off, false)));
          }
          return most;
        };
        double lo = 0.5, hi = 2.5 * extent;
        for (int it = 0; it < 18; ++it) {
          const double mid = 0.5 * (lo + hi);
          (worst(mid) < spec_.cover ? lo : hi) = mid;
        }
        e.size = hi;
      } else {
        // A size like the object's scale; it comes in until `cover` is hidden.
        double size = spec_.shape == OccluderShape::kBar    ? 0.5 * f.across
                      : spec_.shape == OccluderShape::kDisc ? 0.35 * extent
                                                            : 0.8 * extent;
        bool placed = false;
        for (int grow = 0; grow < 8 && !placed; ++grow, size *= 1.3) {
          const double from = -(f.along + reach(spec_.shape, size));
          const auto hides = [&](double off) {
            return hidden_outline_fraction(
                at, parts_at(spec_.shape, size, f, f.centre + f.u * off, true));
          };
          const double step = 2 * -from / 80.0;
          for (int k = 1; k <= 80 && !placed; ++k) {
            if (hides(from + k * step) < spec_.cover) continue;
            // The first place that hides the cover, between this step and the one before.
            double lo = from + (k - 1) * step, hi = from + k * step;
            for (int it = 0; it < 12; ++it) {
              const double mid = 0.5 * (lo + hi);
              (hides(mid) < spec_.cover ? lo : hi) = mid;
            }
            e.stay_offset = hi;
            placed = true;
          }
        }
        e.size = size / 1.3;
        if (!placed) e.stay_offset = 0.0;
      }
      events_.push_back(e);
    }
    start += length + kClearMin + rng.uniform(0, kClearSpread);
  }
}

const OcclusionEvent* OcclusionPlan::event_at(int index) const {
  for (const OcclusionEvent& e : events_) {
    if (index >= e.start && index < e.end()) return &e;
  }
  return nullptr;
}

OcclusionEvent OcclusionPlan::scaled_to(const OcclusionEvent& e, int index) const {
  OcclusionEvent scaled = e;
  if (e.scale > 0.0) {
    const double s = std::sqrt(area(truth_[index])) / e.scale;
    scaled.size *= s;
    scaled.stay_offset *= s;
  }
  return scaled;
}

std::vector<Polygon> OcclusionPlan::occluder_parts(const OcclusionEvent& e, int index) const {
  if (index < 0 || index >= static_cast<int>(truth_.size()) || !usable(truth_[index])) return {};
  const ObjectFrame f = object_frame(truth_[index], e.direction);
  return parts_at(spec_.shape, scaled_to(e, index).size, f, occluder_point(e, index),
                  spec_.motion == OccluderMotion::kStay);
}

Point OcclusionPlan::occluder_point(const OcclusionEvent& e, int index) const {
  const ObjectFrame f = object_frame(truth_[index], e.direction);
  const OcclusionEvent scaled = scaled_to(e, index);
  const double r = reach(spec_.shape, scaled.size);
  return f.centre + f.u * offset_at(scaled, spec_.motion, -(f.along + r), f.along + r, index);
}

double OcclusionPlan::hidden_fraction(int index) const {
  const OcclusionEvent* e = event_at(index);
  if (e == nullptr) return 0.0;
  return hidden_outline_fraction(truth_[index], occluder_parts(*e, index));
}

void OcclusionPlan::draw(int index, cv::Mat* frame) const {
  const OcclusionEvent* e = event_at(index);
  if (e == nullptr || frame->empty()) return;
  const std::vector<Polygon> parts = occluder_parts(*e, index);
  if (parts.empty()) return;
  // An anti-aliased coverage mask, blended over the frame.
  cv::Mat mask = cv::Mat::zeros(frame->size(), CV_8U);
  constexpr int kShift = 4;
  for (const Polygon& part : parts) {
    std::vector<cv::Point> fixed;
    for (const Point& p : part) {
      const double x = std::clamp(p.x, -1e5, 1e5), y = std::clamp(p.y, -1e5, 1e5);
      fixed.emplace_back(static_cast<int>(std::lround(x * (1 << kShift))),
                         static_cast<int>(std::lround(y * (1 << kShift))));
    }
    cv::fillPoly(mask, std::vector<std::vector<cv::Point>>{fixed}, cv::Scalar(255), cv::LINE_AA,
                 kShift);
  }
  cv::Mat tile;
  if (spec_.textured) {
    cv::RNG rng(e->texture_seed);
    tile.create(kTextureTile, kTextureTile, CV_32FC3);
    rng.fill(tile, cv::RNG::NORMAL, 0.0, 60.0);
    cv::GaussianBlur(tile, tile, cv::Size(), 1.5, 1.5, cv::BORDER_REFLECT_101);
  }
  const Point at = occluder_point(*e, index);
  const int channels = frame->channels();
  const double grey = 0.114 * e->colour[0] + 0.587 * e->colour[1] + 0.299 * e->colour[2];
  // The texture moves with the occluder.
  const int ox = static_cast<int>(std::lround(at.x));
  const int oy = static_cast<int>(std::lround(at.y));
  for (int y = 0; y < frame->rows; ++y) {
    const uchar* m = mask.ptr<uchar>(y);
    uchar* px = frame->ptr<uchar>(y);
    for (int x = 0; x < frame->cols; ++x) {
      if (m[x] == 0) continue;
      const double a = m[x] / 255.0;
      double value[3] = {e->colour[0], e->colour[1], e->colour[2]};
      if (!tile.empty()) {
        const int tx = ((x - ox) % kTextureTile + kTextureTile) % kTextureTile;
        const int ty = ((y - oy) % kTextureTile + kTextureTile) % kTextureTile;
        const cv::Vec3f t = tile.at<cv::Vec3f>(ty, tx);
        for (int c = 0; c < 3; ++c) value[c] += t[c];
      }
      if (channels == 1) {
        const double g =
            tile.empty() ? grey : 0.114 * value[0] + 0.587 * value[1] + 0.299 * value[2];
        px[x] = cv::saturate_cast<uchar>(a * g + (1 - a) * px[x]);
      } else {
        for (int c = 0; c < 3; ++c) {
          uchar& v = px[x * channels + c];
          v = cv::saturate_cast<uchar>(a * value[c] + (1 - a) * v);
        }
      }
    }
  }
}

}  // namespace scbt
