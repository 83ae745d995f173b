#include "scbt/peers/ratio_contour.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "scbt/geometry/polygon.h"

namespace scbt {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// A dashed edge of the auxiliary graph: the head of oriented copy `from` joined to the tail of
// copy `to` across a gap.
struct Link {
  int from;
  int to;
  double gap;
  double area;  // signed area of the gap edge plus that of the solid edge of `to`
};

double triangle_area(const Point& reference, const Point& a, const Point& b) {
  return 0.5 * (a - reference).cross(b - reference);
}

bool usable_boundary(const Polygon& polygon, double min_area) {
  return polygon.size() >= 3 &&
         count_distinct_points(polygon) == static_cast<int>(polygon.size()) &&
         area(polygon) >= min_area && is_simple(polygon);
}

}  // namespace

void RatioContourOptions::check() const {
  if (!(initial_ratio > 0.0) || !std::isfinite(initial_ratio)) {
    throw std::invalid_argument("ratio contour initial_ratio must be positive and finite, got " +
                                std::to_string(initial_ratio));
  }
  if (max_iterations < 1) {
    throw std::invalid_argument("ratio contour max_iterations must be >= 1, got " +
                                std::to_string(max_iterations));
  }
  if (!(min_area >= 0.0)) {
    throw std::invalid_argument("ratio contour min_area must be >= 0, got " +
                                std::to_string(min_area));
  }
}

std::vector<int> solve_assignment(const std::vector<double>& cost, int n) {
  if (n < 0 || cost.size() != static_cast<size_t>(n) * n) {
    throw std::invalid_argument("assignment cost matrix must be n x n");
  }
  // Hungarian method with row/column potentials (shortest augmenting paths, O(n^3)). Index 0 is a
  // virtual column that holds the row being inserted.
  std::vector<double> row_potential(n + 1, 0.0), column_potential(n + 1, 0.0);
  std::vector<int> row_of_column(n + 1, 0), previous_column(n + 1, 0);
  std::vector<double> slack(n + 1);
  std::vector<char> visited(n + 1);
  for (int row = 1; row <= n; ++row) {
    row_of_column[0] = row;
    int column = 0;
    std::fill(slack.begin(), slack.end(), kInfinity);
    std::fill(visited.begin(), visited.end(), 0);
    do {
      visited[column] = 1;
      const int r = row_of_column[column];
      const double* costs = &cost[static_cast<size_t>(r - 1) * n];
      double delta = kInfinity;
      int next = -1;
      for (int j = 1; j <= n; ++j) {
        if (visited[j]) continue;
        const double c = costs[j - 1];
        if (c != kInfinity) {
          const double reduced = c - row_potential[r] - column_potential[j];
          if (reduced < slack[j]) {
            slack[j] = reduced;
            previous_column[j] = column;
          }
        }
        if (slack[j] < delta) {
          delta = slack[j];
          next = j;
        }
      }
      if (next < 0) throw std::runtime_error("assignment problem has no finite solution");
      for (int j = 0; j <= n; ++j) {
        if (visited[j]) {
          row_potential[row_of_column[j]] += delta;
          column_potential[j] -= delta;
        } else {
          slack[j] -= delta;
        }
      }
      column = next;
    } while (row_of_column[column] != 0);
    // Flip the augmenting path.
    while (column != 0) {
      const int before = previous_column[column];
      row_of_column[column] = row_of_column[before];
      column = before;
    }
  }
  std::vector<int> column_of_row(n, -1);
  for (int j = 1; j <= n; ++j) column_of_row[row_of_column[j] - 1] = j - 1;
  return column_of_row;
}

std::optional<RatioContour> find_ratio_contour(const SegmentGraph& graph, const Point& reference,
                                               const RatioContourOptions& options) {
  options.check();
  const int num_segments = static_cast<int>(graph.detected_edges.size());
  if (num_segments < 2) return std::nullopt;
  const int n = 2 * num_segments;  // oriented copies: 2k runs u->v, 2k+1 runs v->u

  auto tail = [&](int copy) {
    const GraphEdge& e = graph.edges[graph.detected_edges[copy / 2]];
    return copy % 2 == 0 ? e.u : e.v;
  };
  auto head = [&](int copy) {
    const GraphEdge& e = graph.edges[graph.detected_edges[copy / 2]];
    return copy % 2 == 0 ? e.v : e.u;
  };

  std::vector<std::vector<int>> tails_at(graph.num_vertices());
  for (int c = 0; c < n; ++c) tails_at[tail(c)].push_back(c);
  std::vector<double> solid_area(n);
  for (int c = 0; c < n; ++c) {
    solid_area[c] = triangle_area(reference, graph.vertices[tail(c)], graph.vertices[head(c)]);
  }

  // Dashed edges: same endpoint (gap 0) or a generated edge of the graph (gap = its length).
  std::vector<Link> links;
  for (int from = 0; from < n; ++from) {
    const int h = head(from);
    auto connect = [&](int vertex, double gap) {
      const double gap_area = triangle_area(reference, graph.vertices[h], graph.vertices[vertex]);
      for (int to : tails_at[vertex]) {
        if (to / 2 == from / 2) continue;  // a segment does not continue into itself
        links.push_back({from, to, gap, gap_area + solid_area[to]});
      }
    };
    connect(h, 0.0);
    for (int k = graph.adjacency_begin[h]; k < graph.adjacency_begin[h + 1]; ++k) {
      const GraphEdge& e = graph.edges[graph.adjacency[k].edge];
      if (!e.detected) connect(graph.adjacency[k].vertex, e.weight);
    }
  }
  if (links.empty()) return std::nullopt;

  std::optional<RatioContour> best;
  double lambda = options.initial_ratio;
  bool lambda_from_simple = false;  // the cycle that set lambda is simple (and so is `best`)
  std::vector<double> cost(static_cast<size_t>(n) * n);
  std::vector<int> link_of(static_cast<size_t>(n) * n);
  for (int iteration = 1; iteration <= options.max_iterations; ++iteration) {
    // Row = a copy, column = its successor on a cycle; the diagonal means "not on any cycle".
    std::fill(cost.begin(), cost.end(), kInfinity);
    std::fill(link_of.begin(), link_of.end(), -1);
    for (int c = 0; c < n; ++c) cost[static_cast<size_t>(c) * n + c] = 0.0;
    for (int i = 0; i < static_cast<int>(links.size()); ++i) {
      const Link& l = links[i];
      const size_t at = static_cast<size_t>(l.from) * n + l.to;
      const double c = l.gap - lambda * l.area;
      if (c < cost[at]) {
        cost[at] = c;
        link_of[at] = i;
      }
    }
    const std::vector<int> successor = solve_assignment(cost, n);

    // Walk the cycles of the permutation: the least-ratio one sets the next lambda; the
    // least-ratio simple one is the answer so far.
    std::vector<char> seen(n, 0);
    double next_lambda = lambda;
    bool next_from_simple = false;
    for (int start = 0; start < n; ++start) {
      if (seen[start] || successor[start] == start) continue;
      double gap = 0.0;
      double signed_area = 0.0;
      Polygon polygon;
      int c = start;
      do {
        seen[c] = 1;
        const int s = successor[c];
        const Link& l = links[link_of[static_cast<size_t>(c) * n + s]];
        gap += l.gap;
        signed_area += l.area;
        const Point& p = graph.vertices[tail(s)];
        if (polygon.empty() || polygon.back() != p) polygon.push_back(p);
        polygon.push_back(graph.vertices[head(s)]);
        c = s;
      } while (c != start);
      if (polygon.size() > 1 && polygon.front() == polygon.back()) polygon.pop_back();
      if (!(signed_area > 0.0)) continue;
      const double ratio = gap / signed_area;
      const bool simple = usable_boundary(polygon, options.min_area);
      if (ratio < next_lambda) {
        next_lambda = ratio;
        next_from_simple = simple;
      }
      if (simple && (!best || ratio < best->ratio)) {
        best = RatioContour{polygon, gap, signed_area, ratio, 0, false, 0.0};
      }
    }
    if (best) best->iterations = iteration;
    if (!(next_lambda < lambda * (1.0 - 1e-9))) {
      // No cycle has negative cost at lambda: lambda is the least ratio over all alternate cycles
      // (when lambda came from a cycle at all).
      if (best && lambda_from_simple && best->ratio <= lambda) best->optimal = true;
      break;
    }
    lambda = next_lambda;
    lambda_from_simple = next_from_simple;
  }
  if (best) best->optimum_ratio = lambda;
  return best;
}

}  // namespace scbt
