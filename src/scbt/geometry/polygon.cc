#include "scbt/geometry/polygon.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace scbt {

double Segment::length() const { return cv::norm(b - a); }

double signed_area(const Polygon& polygon) {
  const size_t n = polygon.size();
  if (n < 3) return 0.0;
  double twice_area = 0.0;
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    twice_area += polygon[j].x * polygon[i].y - polygon[i].x * polygon[j].y;
  }
  return 0.5 * twice_area;
}

double area(const Polygon& polygon) { return std::abs(signed_area(polygon)); }

double perimeter(const Polygon& polygon) {
  const size_t n = polygon.size();
  if (n < 2) return 0.0;
  double total = 0.0;
  for (size_t i = 0, j = n - 1; i < n; j = i++) total += cv::norm(polygon[i] - polygon[j]);
  return total;
}

double distance_to_segment(const Point& p, const Point& a, const Point& b) {
  return std::sqrt(distance_sq_to_segment(p, a, b));
}

double distance_to_boundary(const Point& p, const Polygon& polygon) {
  const size_t n = polygon.size();
  if (n == 0) return std::numeric_limits<double>::infinity();
  if (n == 1) return cv::norm(p - polygon[0]);
  // One square root for the least squared distance (the root is monotonic, so this is exactly
  // the least of the distances).
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    best = std::min(best, distance_sq_to_segment(p, polygon[j], polygon[i]));
  }
  return std::sqrt(best);
}

namespace {

// Sign of the turn p -> q -> r: +1 left, -1 right, 0 collinear.
int orientation(const Point& p, const Point& q, const Point& r) {
  const double cross = (q - p).cross(r - p);
  if (cross > 0) return 1;
  if (cross < 0) return -1;
  return 0;
}

bool on_segment(const Point& p, const Point& a, const Point& b) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

// Crossing or touching, collinear overlaps included.
bool segments_intersect(const Point& p1, const Point& p2, const Point& q1, const Point& q2) {
  const int o1 = orientation(p1, p2, q1), o2 = orientation(p1, p2, q2);
  const int o3 = orientation(q1, q2, p1), o4 = orientation(q1, q2, p2);
  if (o1 != o2 && o3 != o4) return true;
  if (o1 == 0 && on_segment(q1, p1, p2)) return true;
  if (o2 == 0 && on_segment(q2, p1, p2)) return true;
  if (o3 == 0 && on_segment(p1, q1, q2)) return true;
  if (o4 == 0 && on_segment(p2, q1, q2)) return true;
  return false;
}

}  // namespace

bool segments_cross(const Point& p1, const Point& p2, const Point& q1, const Point& q2) {
  const int o1 = orientation(p1, p2, q1), o2 = orientation(p1, p2, q2);
  const int o3 = orientation(q1, q2, p1), o4 = orientation(q1, q2, p2);
  return o1 * o2 < 0 && o3 * o4 < 0;
}

int count_distinct_points(const Polygon& polygon) {
  Polygon sorted = polygon;
  std::sort(sorted.begin(), sorted.end(),
            [](const Point& l, const Point& r) { return l.x < r.x || (l.x == r.x && l.y < r.y); });
  return static_cast<int>(std::unique(sorted.begin(), sorted.end()) - sorted.begin());
}

bool is_simple(const Polygon& polygon) {
  const size_t n = polygon.size();
  if (n < 3) return false;
  // Edge e_i runs from vertex i to vertex i + 1. Edges are swept by their left end; only edges
  // whose x ranges overlap can meet, so a typical boundary costs O(n log n) instead of the n^2 / 2
  // pairs (a zigzag whose edges all span the same x range still costs n^2 / 2: see
  // kMaxBoundaryVertices).
  struct Extent {
    double min_x, max_x, min_y, max_y;
  };
  std::vector<Extent> extents(n);
  std::vector<size_t> order(n);
  for (size_t i = 0; i < n; ++i) {
    const Point& a = polygon[i];
    const Point& b = polygon[(i + 1) % n];
    extents[i] = {std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y), std::max(a.y, b.y)};
    order[i] = i;
  }
  std::sort(order.begin(), order.end(),
            [&](size_t l, size_t r) { return extents[l].min_x < extents[r].min_x; });
  std::vector<size_t> active;
  for (const size_t j : order) {
    const Extent& ej = extents[j];
    size_t kept = 0;
    for (const size_t i : active) {
      if (extents[i].max_x < ej.min_x) continue;  // ended left of the sweep: drop it
      active[kept++] = i;
      if (extents[i].max_y < ej.min_y || ej.max_y < extents[i].min_y) continue;
      const size_t lo = std::min(i, j), hi = std::max(i, j);
      const Point& a1 = polygon[lo];
      const Point& a2 = polygon[(lo + 1) % n];
      const Point& b1 = polygon[hi];
      const Point& b2 = polygon[(hi + 1) % n];
      const bool follows = hi == lo + 1;
      if (follows || (lo == 0 && hi == n - 1)) {
        // Adjacent edges share one vertex; they must not fold back onto each other.
        const Point& shared = follows ? a2 : a1;
        const Point& other_a = follows ? a1 : a2;
        const Point& other_b = follows ? b2 : b1;
        if (orientation(other_a, shared, other_b) == 0 &&
            (other_a - shared).dot(other_b - shared) > 0) {
          return false;
        }
        continue;
      }
      if (segments_intersect(a1, a2, b1, b2)) return false;
    }
    active.resize(kept);
    active.push_back(j);
  }
  return true;
}

cv::Rect2d bounding_box(const Polygon& polygon) {
  if (polygon.empty()) return {};
  double min_x = polygon[0].x, max_x = polygon[0].x, min_y = polygon[0].y, max_y = polygon[0].y;
  for (const Point& p : polygon) {
    min_x = std::min(min_x, p.x);
    max_x = std::max(max_x, p.x);
    min_y = std::min(min_y, p.y);
    max_y = std::max(max_y, p.y);
  }
  return {min_x, min_y, max_x - min_x, max_y - min_y};
}

Point centroid(const Polygon& polygon) {
  if (polygon.empty()) return {};
  const double a = signed_area(polygon);
  if (std::abs(a) < 1e-12) {
    Point sum;
    for (const Point& p : polygon) sum += p;
    return sum * (1.0 / static_cast<double>(polygon.size()));
  }
  double cx = 0.0, cy = 0.0;
  const size_t n = polygon.size();
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const double cross = polygon[j].x * polygon[i].y - polygon[i].x * polygon[j].y;
    cx += (polygon[j].x + polygon[i].x) * cross;
    cy += (polygon[j].y + polygon[i].y) * cross;
  }
  return {cx / (6.0 * a), cy / (6.0 * a)};
}

}  // namespace scbt
