// Closed polygons and line segments in image coordinates, and the few measures the tracker needs.
#pragma once

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
// Its square (no square root), for comparisons and minima.
double distance_sq_to_segment(const Point& p, const Point& a, const Point& b);

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
