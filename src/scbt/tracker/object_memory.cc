#include "scbt/tracker/object_memory.h"

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>

namespace scbt {
namespace {

// How far inside and outside the outline its side levels are read (px): past the edge's blur.
constexpr double kSideOffset = 3.0;
// The most a fit may stretch the outline along one direction relative to another since it was
// learnt.
constexpr double kMaxStretch = 2.0;

// Outward unit normals of a closed outline.
std::vector<Point> outward_normals(const Polygon& outline) {
  const size_t n = outline.size();
  const double orientation = signed_area(outline) >= 0.0 ? 1.0 : -1.0;
  std::vector<Point> normals(n);
  for (size_t i = 0; i < n; ++i) {
    const Point t = outline[(i + 1) % n] - outline[(i + n - 1) % n];
    const double len = std::max(1e-9, std::hypot(t.x, t.y));
    normals[i] = Point(t.y, -t.x) * (orientation / len);
  }
  return normals;
}

// Bilinear grey level at frame point p of the window `gray` at `tl`; false outside it.
bool grey_at(const cv::Mat& gray, cv::Point tl, Point p, double* value) {
  const double x = p.x - tl.x, y = p.y - tl.y;
  if (!(x >= 0.0 && y >= 0.0 && x < gray.cols - 1 && y < gray.rows - 1)) return false;
  const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
  const double fx = x - x0, fy = y - y0;
  const uchar* r0 = gray.ptr<uchar>(y0) + x0;
  const uchar* r1 = gray.ptr<uchar>(y0 + 1) + x0;
  *value = (1 - fy) * ((1 - fx) * r0[0] + fx * r0[1]) + fy * ((1 - fx) * r1[0] + fx * r1[1]);
  return true;
}

// The grey step across the outline at p + k n (outside minus inside, over 2 px); false outside
// the window.
bool step_at(const cv::Mat& gray, cv::Point tl, Point p, Point n, double k, double* step) {
  double out = 0.0, in = 0.0;
  if (!grey_at(gray, tl, p + n * (k + 1.0), &out) || !grey_at(gray, tl, p + n * (k - 1.0), &in)) {
    return false;
  }
  *step = out - in;
  return true;
}

// The point of closed polygon `polygon` nearest to `p`.
Point closest_point_on(const Polygon& polygon, const Point& p) {
  Point best = polygon.front();
  double best_d2 = 1e300;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Point a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    const Point e = b - a;
    const double len2 = e.dot(e);
    const double t = len2 > 0.0 ? std::clamp((p - a).dot(e) / len2, 0.0, 1.0) : 0.0;
    const Point q = a + e * t;
    const double d2 = (q - p).dot(q - p);
    if (d2 < best_d2) {
      best_d2 = d2;
      best = q;
    }
  }
  return best;
}

// The linear part of the affine map taking `from` onto `to` (corresponding points, least
// squares about their centroids); the identity when it cannot be told.
cv::Matx22d linear_map(const Polygon& from, const Polygon& to) {
  if (from.size() != to.size() || from.size() < 3) return cv::Matx22d::eye();
  Point cf(0, 0), ct(0, 0);
  for (size_t i = 0; i < from.size(); ++i) {
    cf += from[i];
    ct += to[i];
  }
  cf *= 1.0 / from.size();
  ct *= 1.0 / to.size();
  cv::Matx22d ff = cv::Matx22d::zeros(), tf = cv::Matx22d::zeros();
  for (size_t i = 0; i < from.size(); ++i) {
    const cv::Vec2d f(from[i].x - cf.x, from[i].y - cf.y), t(to[i].x - ct.x, to[i].y - ct.y);
    ff += f * f.t();
    tf += t * f.t();
  }
  if (std::abs(cv::determinant(ff)) < 1e-9) return cv::Matx22d::eye();
  return tf * ff.inv();
}

}  // namespace

double agreement_distance(const Polygon& outline) {
  return std::max(3.0, 0.05 * std::sqrt(std::max(1.0, area(outline))));
}

Polygon resample_outline(const Polygon& polygon, int n) {
  Polygon out;
  const double total = perimeter(polygon);
  if (polygon.size() < 2 || !(total > 0.0) || n <= 0) return out;
  out.reserve(n);
  size_t edge = 0;
  double edge_start = 0.0;  // arc length at polygon[edge]
  for (int k = 0; k < n; ++k) {
    const double s = total * k / n;
    for (;;) {
      const Point a = polygon[edge], b = polygon[(edge + 1) % polygon.size()];
      const double len = std::hypot(b.x - a.x, b.y - a.y);
      if (s <= edge_start + len || edge + 1 == polygon.size()) {
        const double t = len > 0.0 ? std::clamp((s - edge_start) / len, 0.0, 1.0) : 0.0;
        out.push_back(a + (b - a) * t);
        break;
      }
      edge_start += len;
      ++edge;
    }
  }
  return out;
}

void ObjectMemory::clear() {
  anchor_model_.clear();
  placed_.clear();
  learnt_.clear();
  polarity_.clear();
  contrast_.clear();
  inside_.clear();
  outside_.clear();
}

void ObjectMemory::restart(const Polygon& boundary, const cv::Mat& gray, cv::Point tl) {
  clear();
  anchor_model_ = resample_outline(boundary, options_.points);
  if (anchor_model_.size() < 3) {
    clear();
    return;
  }
  placed_ = anchor_model_;
  learnt_ = placed_;
  polarity_.assign(placed_.size(), 0.0);
  contrast_.assign(placed_.size(), 0.0);
  inside_.assign(placed_.size(), -1.0);
  outside_.assign(placed_.size(), -1.0);
  read_edges(gray, tl);
}

void ObjectMemory::remember(const Polygon& boundary, const cv::Mat& gray, cv::Point tl,
                            double shape_rate) {
  if (!ready()) {
    restart(boundary, gray, tl);
    return;
  }
  // The memory takes the boundary's place and view; its shape changes only by `shape_rate`, so
  // that a cycle eaten into by an occluder a little each frame cannot wear the outline away.
  const size_t n = anchor_model_.size();
  Polygon mapped = placed_;
  if (!map_anchor_onto(boundary, &mapped)) return;
  if (shape_rate > 0.0) {
    for (Point& p : mapped) p += (closest_point_on(boundary, p) - p) * shape_rate;
    // Evenly spaced again (closest points bunch at corners); the anchor is the new shape.
    mapped = resample_outline(mapped, static_cast<int>(n));
    if (mapped.size() != n) return;
    anchor_model_ = mapped;
  }
  placed_ = mapped;
  learnt_ = placed_;
  read_edges(gray, tl);
}

void ObjectMemory::place_onto(const Polygon& boundary, const cv::Mat& gray, cv::Point tl) {
  Polygon mapped = mapped_onto(boundary);
  if (mapped.empty()) return;
  placed_ = std::move(mapped);
  learnt_ = placed_;
  read_edges(gray, tl);
}

bool ObjectMemory::map_anchor_onto(const Polygon& boundary, Polygon* mapped) const {
  // An affine map of the anchor fitted to the closest points of `boundary`, a few rounds from
  // *mapped. Points farther from the boundary than twice the agreement distance weigh nothing
  // (Tukey's biweight): where a cycle that agrees overall cuts across an occluder, its cut must
  // not drag the outline with it.
  const size_t n = anchor_model_.size();
  const double cutoff = 2.0 * agreement_distance(boundary);
  for (int round = 0; round < 4; ++round) {
    cv::Matx33d ata = cv::Matx33d::zeros();
    cv::Vec3d atx(0, 0, 0), aty(0, 0, 0);
    double weight_sum = 0.0;
    for (size_t i = 0; i < n; ++i) {
      const Point target = closest_point_on(boundary, (*mapped)[i]);
      const double u = std::hypot(target.x - (*mapped)[i].x, target.y - (*mapped)[i].y) / cutoff;
      const double w = u < 1.0 ? (1 - u * u) * (1 - u * u) : 0.0;
      const cv::Vec3d row(anchor_model_[i].x, anchor_model_[i].y, 1.0);
      ata += w * row * row.t();
      atx += w * target.x * row;
      aty += w * target.y * row;
      weight_sum += w;
    }
    // Too little of the outline on the boundary to place it: the place reached stays.
    if (weight_sum < 0.5 * static_cast<double>(n)) break;
    cv::Mat ax, ay;
    if (!cv::solve(cv::Mat(ata), cv::Mat(atx), ax, cv::DECOMP_CHOLESKY) ||
        !cv::solve(cv::Mat(ata), cv::Mat(aty), ay, cv::DECOMP_CHOLESKY)) {
      return false;
    }
    for (size_t i = 0; i < n; ++i) {
      const Point& p = anchor_model_[i];
      (*mapped)[i] = Point(ax.at<double>(0) * p.x + ax.at<double>(1) * p.y + ax.at<double>(2),
                           ay.at<double>(0) * p.x + ay.at<double>(1) * p.y + ay.at<double>(2));
    }
  }
  return true;
}

Polygon ObjectMemory::mapped_onto(const Polygon& outline) const {
  if (!ready() || outline.size() < 3) return {};
  // From the last place moved and scaled onto `outline`: the robust map then starts near it.
  Polygon mapped = placed_;
  const double scale = std::sqrt(std::max(1e-9, area(outline)) / std::max(1e-9, area(placed_)));
  const Point from = centroid(placed_), to = centroid(outline);
  for (Point& p : mapped) p = to + (p - from) * scale;
  if (!map_anchor_onto(outline, &mapped)) return {};
  return mapped;
}

MemoryFit ObjectMemory::fit_at(const Polygon& outline, const cv::Mat& gray, cv::Point tl) const {
  // A copy is placed on `outline` and fitted there: the memory's own place is not touched. Held
  // to the view found there, not to the one last learnt.
  ObjectMemory probe = *this;
  probe.placed_ = mapped_onto(outline);
  if (probe.placed_.empty()) return {};
  probe.learnt_ = probe.placed_;
  return probe.fit(gray, tl);
}

void ObjectMemory::read_edges(const cv::Mat& gray, cv::Point tl) {
  const std::vector<Point> normals = outward_normals(placed_);
  for (size_t i = 0; i < placed_.size(); ++i) {
    // The strongest step within a pixel of the outline: a traced outline sits on its edge to a
    // pixel or so. Where none is clear (hidden, or faint there) the point keeps what it had.
    double best = 0.0;
    for (double k : {-1.0, 0.0, 1.0}) {
      double step = 0.0;
      if (step_at(gray, tl, placed_[i], normals[i], k, &step) && std::abs(step) > std::abs(best)) {
        best = step;
      }
    }
    if (std::abs(best) < options_.min_step) continue;
    double in = 0.0, out = 0.0;
    if (grey_at(gray, tl, placed_[i] - normals[i] * kSideOffset, &in) &&
        grey_at(gray, tl, placed_[i] + normals[i] * kSideOffset, &out)) {
      inside_[i] = in;
      outside_[i] = out;
    }
    polarity_[i] = best > 0.0 ? 1.0 : -1.0;
    contrast_[i] = std::abs(best);
  }
}

MemoryFit ObjectMemory::search(const cv::Mat& gray, cv::Point tl, double radius,
                               double accept_visible) {
  const Polygon start = placed_;
  // Starting places two search reaches apart: every place within `radius` is within one reach
  // (along each axis) of one of them.
  const double spacing = 2.0 * options_.search_px;
  const int steps = static_cast<int>(std::ceil(radius / spacing));
  MemoryFit best;
  double best_distance = 0.0;
  for (int iy = -steps; iy <= steps; ++iy) {
    for (int ix = -steps; ix <= steps; ++ix) {
      placed_ = start;
      const Point shift(ix * spacing, iy * spacing);
      for (Point& p : placed_) p += shift;
      const MemoryFit f = fit(gray, tl);
      if (!f.valid) continue;
      // Ties go to the nearer start: the object moves little between frames.
      const double distance = std::hypot(shift.x, shift.y);
      if (!best.valid || f.visible > best.visible ||
          (f.visible == best.visible && distance < best_distance)) {
        best = f;
        best_distance = distance;
      }
    }
  }
  if (!best.valid || best.visible < accept_visible) {
    placed_ = start;
    return {};
  }
  placed_ = best.outline;
  return best;
}

MemoryFit ObjectMemory::fit(const cv::Mat& gray, cv::Point tl) {
  MemoryFit result;
  if (!ready() || gray.empty()) return result;
  const size_t n = placed_.size();
  int with_edge = 0;
  for (double p : polarity_) with_edge += p != 0.0 ? 1 : 0;
  if (with_edge < static_cast<int>(n) / 4) return result;

  Polygon current = placed_;
  std::vector<Point> targets(n);
  std::vector<double> found(n);  // offsets found along the normal; NaN: none
  // Looks along each point's normal for the nearest strong step of its polarity, within `reach`.
  const auto search = [&](double reach, const std::vector<Point>& normals) {
    int matched = 0;
    for (size_t i = 0; i < n; ++i) {
      found[i] = std::nan("");
      if (polarity_[i] == 0.0) continue;
      const double need = edge_need(i);
      double best_score = 0.0;
      for (double k = -reach; k <= reach; k += 1.0) {
        double step = 0.0;
        if (!step_at(gray, tl, current[i], normals[i], k, &step)) continue;
        const double response = polarity_[i] * step;
        if (response < need) continue;
        if (!sides_match(gray, tl, current[i] + normals[i] * k, normals[i], i)) continue;
        const double score = response * (1.0 - 0.5 * std::abs(k) / (reach + 1.0));
        if (score > best_score) {
          best_score = score;
          found[i] = k;
        }
      }
      if (!std::isnan(found[i])) {
        targets[i] = current[i] + normals[i] * found[i];
        ++matched;
      }
    }
    return matched;
  };

  for (int round = 0; round < 3; ++round) {
    const std::vector<Point> normals = outward_normals(current);
    const int matched = search(round == 0 ? options_.search_px : 4.0, normals);
    if (matched < with_edge / 4 || matched < 6) return result;
    Point centre(0, 0);
    for (const Point& p : current) centre += p;
    centre *= 1.0 / n;
    // An affine map x -> A (x - c) + c + t fitted point-to-line, A = [[a + d, e - b], [b + e,
    // a - d]]: (a, b) its rotation and scale, (d, e) the stretch a change of view adds to a flat
    // outline (a rim seen from higher up is a rounder ellipse). Reweighted against outliers and
    // held towards no change so that a visible side alone does not tilt or stretch it.
    double a = 1.0, b = 0.0, d = 0.0, e = 0.0, tx = 0.0, ty = 0.0;
    for (int irls = 0; irls < 4; ++irls) {
      cv::Matx66d ata = cv::Matx66d::zeros();
      cv::Vec6d atb(0, 0, 0, 0, 0, 0);
      double weight_sum = 0.0;
      for (size_t i = 0; i < n; ++i) {
        if (std::isnan(found[i])) continue;
        const Point c = current[i] - centre;
        const Point& nn = normals[i];
        const cv::Vec6d row(nn.x * c.x + nn.y * c.y, nn.y * c.x - nn.x * c.y,
                            nn.x * c.x - nn.y * c.y, nn.x * c.y + nn.y * c.x, nn.x, nn.y);
        const double rhs = nn.dot(targets[i] - centre);
        const double predicted = row.dot(cv::Vec6d(a, b, d, e, tx, ty));
        const double r = std::abs(predicted - rhs);
        // Huber on the first pass, then Tukey's biweight: an occluder's edge of the object's
        // polarity next to the hidden outline must not pull the fit at all.
        double w = r <= options_.inlier_px ? 1.0 : options_.inlier_px / r;
        if (irls > 0) {
          const double u = r / (2.0 * options_.inlier_px);
          w = u < 1.0 ? (1 - u * u) * (1 - u * u) : 0.0;
        }
        ata += w * row * row.t();
        atb += w * rhs * row;
        weight_sum += w;
      }
      // Held towards a = 1 and b = d = e = 0 in units of the outline's size.
      double radius = 0.0;
      for (const Point& p : current) radius += std::hypot(p.x - centre.x, p.y - centre.y);
      radius /= n;
      const double hold = 0.05 * weight_sum * radius * radius;
      ata(0, 0) += hold;
      ata(1, 1) += hold;
      ata(2, 2) += hold;
      ata(3, 3) += hold;
      atb[0] += hold;
      cv::Mat solution;
      if (!cv::solve(cv::Mat(ata), cv::Mat(atb), solution, cv::DECOMP_CHOLESKY)) return result;
      a = solution.at<double>(0);
      b = solution.at<double>(1);
      d = solution.at<double>(2);
      e = solution.at<double>(3);
      tx = solution.at<double>(4);
      ty = solution.at<double>(5);
    }
    for (Point& p : current) {
      const Point c = p - centre;
      p = centre + Point((a + d) * c.x + (e - b) * c.y + tx, (b + e) * c.x + (a - d) * c.y + ty);
    }
  }
  // Seen from another angle an outline flattens or rounds (a rim by up to the 1.5 the view-change
  // search allows). A fit stretched twice as much along one direction as along another since a
  // boundary was last learnt, or squeezed to half along one, has pulled the outline onto edges
  // inside its visible part (a rim's inner edge, a liquid's surface) and says nothing. Growing
  // alike in every direction (a camera coming closer) is not limited.
  cv::Matx22d u, vt;
  cv::Matx21d stretch;
  cv::SVD::compute(linear_map(learnt_, current), stretch, u, vt);
  if (!(stretch(0) <= kMaxStretch * stretch(1) && stretch(1) >= 1.0 / kMaxStretch)) return result;
  // Visible: points whose edge is where the fit put them.
  const std::vector<Point> normals = outward_normals(current);
  search(options_.inlier_px, normals);
  int visible = 0;
  for (size_t i = 0; i < n; ++i) visible += std::isnan(found[i]) ? 0 : 1;
  result.valid = true;
  result.outline = current;
  result.visible = static_cast<double>(visible) / with_edge;
  placed_ = current;
  return result;
}

bool ObjectMemory::sides_match(const cv::Mat& gray, cv::Point tl, Point p, Point normal,
                               size_t point) const {
  if (inside_[point] < 0.0) return true;  // not known
  double in = 0.0, out = 0.0;
  if (!grey_at(gray, tl, p - normal * kSideOffset, &in) ||
      !grey_at(gray, tl, p + normal * kSideOffset, &out)) {
    return true;
  }
  // What surrounds the object changes more as it moves than the object's own side.
  const double step = std::abs(outside_[point] - inside_[point]);
  return std::abs(in - inside_[point]) <= std::max(20.0, 0.35 * step) &&
         std::abs(out - outside_[point]) <= std::max(30.0, 0.5 * step);
}

double ObjectMemory::departure_support(const Polygon& cycle, const Polygon& fitted, double distance,
                                       const cv::Mat& gray, cv::Point tl) const {
  if (!ready() || fitted.size() != anchor_model_.size()) return 1.0;
  const Polygon samples = resample_outline(cycle, options_.points);
  if (samples.size() < 3) return 1.0;
  const std::vector<Point> normals = outward_normals(samples);
  int departing = 0, supported = 0;
  for (size_t i = 0; i < samples.size(); ++i) {
    if (distance_to_boundary(samples[i], fitted) <= distance) continue;
    ++departing;
    size_t nearest = 0;
    double best = 1e300;
    for (size_t j = 0; j < fitted.size(); ++j) {
      const Point d = fitted[j] - samples[i];
      if (d.dot(d) < best) {
        best = d.dot(d);
        nearest = j;
      }
    }
    if (!own_edge_near(nearest, gray, tl, samples[i], normals[i])) continue;
    ++supported;
  }
  return departing == 0 ? 1.0 : static_cast<double>(supported) / departing;
}

double ObjectMemory::edge_need(size_t point) const {
  return std::max(options_.min_step, 0.4 * contrast_[point]);
}

bool ObjectMemory::own_edge_near(size_t point, const cv::Mat& gray, cv::Point tl, Point p,
                                 Point normal) const {
  for (double k : {-1.0, 0.0, 1.0}) {
    double step = 0.0;
    if (!step_at(gray, tl, p, normal, k, &step)) continue;
    const double response = polarity_[point] != 0.0 ? polarity_[point] * step : std::abs(step);
    if (response >= edge_need(point)) {
      // The object's edge has the object on its inside and what surrounds it outside.
      return sides_match(gray, tl, p, normal, point);
    }
  }
  return false;
}

double ObjectMemory::explained_by(const Polygon& cycle, const Polygon& fitted, double distance,
                                  const cv::Mat& gray, cv::Point tl) const {
  if (!ready() || fitted.size() != anchor_model_.size() || cycle.size() < 3) return 0.0;
  const std::vector<Point> normals = outward_normals(fitted);
  int with_edge = 0, explained = 0;
  for (size_t i = 0; i < fitted.size(); ++i) {
    if (polarity_[i] == 0.0) continue;
    ++with_edge;
    const Point on_cycle = closest_point_on(cycle, fitted[i]);
    const Point d = on_cycle - fitted[i];
    if (d.dot(d) > distance * distance) continue;
    if (own_edge_near(i, gray, tl, on_cycle, normals[i])) ++explained;
  }
  return with_edge == 0 ? 0.0 : static_cast<double>(explained) / with_edge;
}

double ObjectMemory::mismatch(const Polygon& outline, const Polygon& other, double distance) const {
  const auto far_fraction = [distance, this](const Polygon& from, const Polygon& to) {
    const Polygon samples = resample_outline(from, options_.points);
    if (samples.empty() || to.size() < 3) return 1.0;
    int far = 0;
    for (const Point& p : samples) far += distance_to_boundary(p, to) > distance ? 1 : 0;
    return static_cast<double>(far) / samples.size();
  };
  return std::max(far_fraction(outline, other), far_fraction(other, outline));
}

}  // namespace scbt
