// Finding a lost object again: where in the frame could the last confident boundary be? Places
// of its outline (translated, at a few scales) are ranked by chamfer distance to the frame's line
// segments, first near where the object was, then over the whole frame. The tracker then runs
// its ordinary search around each place and keeps a cycle only if its shape matches
// (track_state.h, LossOptions).
#pragma once

#include <opencv2/core/mat.hpp>
#include <vector>

#include "scbt/geometry/polygon.h"

namespace scbt {

struct Placement {
  Polygon outline;       // the template moved (and scaled) there: the prior of a search
  double chamfer = 0.0;  // mean distance (pixels, capped) from the outline's samples to a segment
  bool near = false;     // within the near region of the last position
  double scale = 1.0;    // of the outline against the template
};

struct PlacementOptions {
  double min_scale = 0.75;
  double max_scale = 1.33;
  // Scales are tried from min_scale in steps of this ratio: the search around a placement
  // follows the outline within the tracker's filter band, so a few per cent of size between steps
  // is found anyway.
  double scale_step = 1.1;
  // Placements worse than this share of the cap are not worth a search.
  double max_chamfer_share = 0.8;
  // Placements are tried with at least this share of the outline inside the frame (the rest
  // counts as the cap): an object coming back may still be cut by the frame's edge.
  double min_inside_share = 0.75;
  int near_tries = 2;
  int frame_tries = 3;
};

// `outline` scaled by `factor` along the minor axis of its inertia ellipse, about its centroid: a
// rim seen from a little lower (factor < 1: flatter) or higher (> 1: rounder). A plane turning
// about the axis it is seen along keeps that axis and shortens the other.
Polygon foreshortened(const Polygon& outline, double factor);

class Reacquirer {
 public:
  // The frame's segments to rank placements against. Distances beyond `cap` count as `cap`
  // (pixels): a missing piece of outline costs a bounded amount (the tracker passes half its
  // filter distance).
  void set_segments(const std::vector<Segment>& segments, cv::Size frame_size, double cap);
  // The best placements of `outline` over the segments: up to near_tries within one outline
  // size of its current position, then up to frame_tries anywhere (near ones included), best
  // first, no two of the same scale closer than a quarter of the outline's size. Empty when there
  // are no segments.
  std::vector<Placement> rank(const Polygon& outline, const PlacementOptions& options) const;

 private:
  bool empty_ = true;
  double cap_ = 10.0;
  cv::Mat edges_;     // segments drawn as 0 on 255
  cv::Mat distance_;  // distance transform of edges_, CV_32F
};

}  // namespace scbt
