#include "scbt/choice/boundary_distance_cache.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "scbt/geometry/avx2_clones.h"
#include "scbt/geometry/segment_distance_row.h"

namespace scbt {
namespace {

constexpr double kNotComputed = std::numeric_limits<double>::quiet_NaN();

}  // namespace

void BoundaryDistanceCache::reset(const SegmentGraph& graph, const Polygon& previous,
                                  const KnownSegmentDistances* known) {
  graph_ = &graph;
  previous_ = &previous;
  query_.reset(previous);
  vertex_distance_.assign(graph.vertices.size(), kNotComputed);
  midpoint_distance_.assign(graph.edges.size(), kNotComputed);
  edge_term_.assign(2 * graph.edges.size(), EdgeTerm{kNotComputed, kNotComputed});
  row_offset_.assign(graph.edges.size(), -1);
  rows_.clear();

  // Samples in the order boundary_distance visits them: edge (j, i) for i = 0.. with j = i - 1
  // cyclically contributes its start j, its midpoint and its end i.
  const size_t n = previous.size();
  sample_x_.resize(2 * n);
  sample_y_.resize(2 * n);
  previous_edge_length_.resize(n);
  previous_length_ = 0.0;
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point midpoint = (previous[j] + previous[i]) * 0.5;  // of the edge into i
    sample_x_[2 * i] = previous[i].x;
    sample_y_[2 * i] = previous[i].y;
    sample_x_[2 * i + 1] = midpoint.x;
    sample_y_[2 * i + 1] = midpoint.y;
    previous_edge_length_[i] = cv::norm(previous[i] - previous[j]);
    previous_length_ += previous_edge_length_[i];
  }
  if (known && known->segments && known->distances) take_known(*known);
}

void BoundaryDistanceCache::take_known(const KnownSegmentDistances& known) {
  const SegmentGraph& g = *graph_;
  const std::vector<Segment>& segments = *known.segments;
  const std::vector<double>& distances = *known.distances;
  if (distances.size() != 3 * segments.size()) return;
  // The graph's detected edges follow the segments' order, leaving out zero-length ones and
  // repeats: walk both, and take a segment's distances only where its endpoints are exactly
  // the edge's (then its midpoint is the edge's too). Any mismatch merely leaves distances to
  // be computed on demand.
  size_t next = 0;
  for (size_t i = 0; i < segments.size() && next < g.detected_edges.size(); ++i) {
    const int edge = g.detected_edges[next];
    const GraphEdge& e = g.edges[edge];
    if (!(g.vertices[e.u] == segments[i].a && g.vertices[e.v] == segments[i].b)) continue;
    vertex_distance_[e.u] = distances[3 * i];
    vertex_distance_[e.v] = distances[3 * i + 1];
    midpoint_distance_[edge] = distances[3 * i + 2];
    ++next;
  }
}

int BoundaryDistanceCache::edge_between(int u, int v) const {
  const SegmentGraph& g = *graph_;
  if (static_cast<size_t>(u) + 1 >= g.adjacency_begin.size()) return -1;
  for (int k = g.adjacency_begin[u]; k < g.adjacency_begin[u + 1]; ++k) {
    if (g.adjacency[k].vertex == v) return g.adjacency[k].edge;
  }
  return -1;
}

double BoundaryDistanceCache::vertex_distance(int v) {
  double& d = vertex_distance_[v];
  if (std::isnan(d)) d = query_.distance(graph_->vertices[v], &hint_);
  return d;
}

double BoundaryDistanceCache::midpoint_distance(int edge, const Point& a, const Point& b) {
  if (edge < 0) return query_.distance((a + b) * 0.5, &hint_);
  double& d = midpoint_distance_[edge];
  if (std::isnan(d)) d = query_.distance((a + b) * 0.5, &hint_);
  return d;
}

BoundaryDistanceCache::EdgeTerm BoundaryDistanceCache::edge_term(int edge, int from, int to) {
  const Point& a = graph_->vertices[from];
  const Point& b = graph_->vertices[to];
  EdgeTerm term;
  term.length = cv::norm(b - a);
  const double mid = midpoint_distance(edge, a, b);
  term.weighted = term.length * (vertex_distance(from) + 4.0 * mid + vertex_distance(to)) / 6.0;
  return term;
}

double BoundaryDistanceCache::mean_distance_from_cycle(const std::vector<int>& cycle,
                                                       std::vector<int>* edges) {
  const size_t n = cycle.size();
  double weighted = 0.0, total_length = 0.0;
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const int edge = edge_between(cycle[j], cycle[i]);
    if (edges) edges->push_back(edge);
    EdgeTerm term;
    if (edge >= 0) {
      // Near-tied cycles share most edges: each edge's term is computed once per direction.
      EdgeTerm& cached = edge_term_[2 * edge + (graph_->edges[edge].u == cycle[j] ? 0 : 1)];
      if (std::isnan(cached.weighted)) cached = edge_term(edge, cycle[j], cycle[i]);
      term = cached;
    } else {
      term = edge_term(edge, cycle[j], cycle[i]);
    }
    weighted += term.weighted;
    total_length += term.length;
  }
  return total_length > 0.0 ? weighted / total_length : 0.0;
}

const double* BoundaryDistanceCache::sample_distances_sq(int edge, const Point& a, const Point& b) {
  const size_t m = sample_x_.size();
  double* row;
  if (edge >= 0 && row_offset_[edge] >= 0) return rows_.data() + row_offset_[edge];
  if (edge >= 0) {
    row_offset_[edge] = static_cast<int>(rows_.size());
    rows_.resize(rows_.size() + m);
    row = rows_.data() + row_offset_[edge];
  } else {
    scratch_row_.resize(m);
    row = scratch_row_.data();
  }
  distance_sq_row_to_segment(sample_x_.data(), sample_y_.data(), m, a, b, row);
  return row;
}

namespace {

// nearest[s] = min(nearest[s], row[s]) for s < m; with AVX2 four samples per instruction (a
// minimum is exact at any width).
SCBT_AVX2_CLONES void take_minima(double* __restrict nearest, const double* __restrict row,
                                  size_t m) {
  for (size_t s = 0; s < m; ++s) nearest[s] = std::min(nearest[s], row[s]);
}

}  // namespace

double BoundaryDistanceCache::mean_distance_to_cycle(const std::vector<int>& cycle,
                                                     const int* edges) {
  const size_t m = sample_x_.size();
  const size_t n = cycle.size();
  if (m == 0 || !(previous_length_ > 0.0)) return 0.0;
  nearest_sq_.assign(m, std::numeric_limits<double>::infinity());
  const std::vector<Point>& points = graph_->vertices;
  if (n == 1) {
    for (size_t s = 0; s < m; ++s) {
      const Point d = Point(sample_x_[s], sample_y_[s]) - points[cycle[0]];
      nearest_sq_[s] = d.x * d.x + d.y * d.y;
    }
  }
  for (size_t i = 0, j = n - 1; n > 1 && i < n; j = i++) {
    const int edge = edges ? edges[i] : edge_between(cycle[j], cycle[i]);
    // Rows are cached in the graph's orientation of the edge, so the same edge walked either
    // way gives the same values.
    const bool forward = edge < 0 || graph_->edges[edge].u == cycle[j];
    const Point& a = points[forward ? cycle[j] : cycle[i]];
    const Point& b = points[forward ? cycle[i] : cycle[j]];
    const double* row = sample_distances_sq(edge, a, b);
    // sample_distances_sq may grow rows_; `row` stays valid until the next call.
    take_minima(nearest_sq_.data(), row, m);
  }
  const size_t count = m / 2;
  double weighted = 0.0;
  for (size_t i = 0, j = count - 1; i < count; j = i++) {
    weighted += previous_edge_length_[i] *
                (std::sqrt(nearest_sq_[2 * j]) + 4.0 * std::sqrt(nearest_sq_[2 * i + 1]) +
                 std::sqrt(nearest_sq_[2 * i])) /
                6.0;
  }
  return weighted / previous_length_;
}

}  // namespace scbt
