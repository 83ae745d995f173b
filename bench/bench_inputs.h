// Inputs the micro-benchmarks share, generated in code at the dataset's scale.
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "scbt/geometry/polygon.h"

namespace scbt::bench_inputs {

// A boundary of 16 vertices on an ellipse around the centre of a 640x480 frame.
inline Polygon make_boundary() {
  Polygon boundary;
  for (int k = 0; k < 16; ++k) {
    const double t = 2.0 * M_PI * k / 16.0;
    boundary.push_back({320.0 + 150.0 * std::cos(t), 240.0 + 100.0 * std::sin(t)});
  }
  return boundary;
}

// `count` segments: about two thirds are broken, jittered pieces of the boundary's sides (with
// gaps), the rest distractors within 15 px of it.
inline std::vector<Segment> make_segments(const Polygon& boundary, int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0), jitter(-1.0, 1.0), offset(-15.0, 15.0);
  std::vector<Segment> segments;
  const int n = static_cast<int>(boundary.size());
  const int on_boundary = count * 2 / 3;
  const int pieces = std::max(1, on_boundary / n);
  for (int i = 0; i < n; ++i) {
    const Point a = boundary[i], b = boundary[(i + 1) % n];
    for (int k = 0; k < pieces; ++k) {
      const double t0 = (k + 0.1 * unit(rng)) / pieces, t1 = (k + 0.8 + 0.1 * unit(rng)) / pieces;
      segments.push_back({a + (b - a) * t0 + Point(jitter(rng), jitter(rng)),
                          a + (b - a) * t1 + Point(jitter(rng), jitter(rng))});
    }
  }
  while (static_cast<int>(segments.size()) < count) {
    const Point p = boundary[static_cast<int>(unit(rng) * n) % n] + Point(offset(rng), offset(rng));
    const double angle = 2.0 * M_PI * unit(rng), length = 8.0 + 30.0 * unit(rng);
    segments.push_back({p, p + Point(std::cos(angle), std::sin(angle)) * length});
  }
  return segments;
}

}  // namespace scbt::bench_inputs
