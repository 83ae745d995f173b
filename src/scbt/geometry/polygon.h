// Closed polygons and line segments in image coordinates, and the few measures the tracker needs.
#pragma once

#include <algorithm>
#include <opencv2/core/types.hpp>
#include <vector>

namespace scbt {

using Point = cv::Point2d;

// A closed boundary: the last vertex connects back to the first.
using Polygon = std::vector<Point>;

// A straight line segment between two endpoints.
struct Segment {
  Point a;
  Point b;

  Point midpoint() const { return (a + b) * 0.5; }
  double length() const;
};

// Shoelace area, positive for counter-clockwise vertex order in a y-up frame
// (clockwise as drawn on an image, whose y axis points down).
double signed_area(const Polygon& polygon);

// |signed_area|: the area the closed boundary encloses (for a simple polygon).
double area(const Polygon& polygon);

double perimeter(const Polygon& polygon);

// Distance from `p` to the closed polyline `polygon` (its edges, not its interior).
double distance_to_boundary(const Point& p, const Polygon& polygon);

double distance_to_segment(const Point& p, const Point& a, const Point& b);
// Its square (no square root), for comparisons and minima. Inline: the distance queries call it
// in their innermost loops (a call per boundary edge or per sample), where inlining it let the
// loops be optimised as a whole.
inline double distance_sq_to_segment(const Point& p, const Point& a, const Point& b) {
  const Point ab = b - a;
  const double length_sq = ab.dot(ab);
  double t = length_sq > 0.0 ? (p - a).dot(ab) / length_sq : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const Point d = p - (a + t * ab);
  return d.x * d.x + d.y * d.y;
}

// True when segments [p1,p2] and [q1,q2] cross at a point interior to both
// (touching at endpoints or collinear overlap does not count).
bool segments_cross(const Point& p1, const Point& p2, const Point& q1, const Point& q2);

// Number of pairwise distinct vertices.
int count_distinct_points(const Polygon& polygon);

// True when no two non-adjacent edges of the closed polygon cross or touch.
bool is_simple(const Polygon& polygon);

// Axis-aligned bounding box of the vertices (empty rect for an empty polygon).
cv::Rect2d bounding_box(const Polygon& polygon);

// Mean of the vertices' positions weighted by area (the centroid of the enclosed region);
// falls back to the vertex mean for degenerate polygons.
Point centroid(const Polygon& polygon);

}  // namespace scbt
