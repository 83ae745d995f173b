// How far to trust a tracked boundary: evidence the tracker already has about the cycle it chose,
// combined into a confidence in [0, 1] by a logistic model calibrated on rendered scenes
// (docs/loss-handling.md, bench/fit_confidence.py).
#pragma once

#include <opencv2/core/mat.hpp>

#include "scbt/geometry/polygon.h"
#include "scbt/geometry/shape_descriptor.h"

namespace scbt {

// What the chosen cycle looks like. Each value is cheap (a few microseconds per frame).
struct BoundaryEvidence {
  // |B_G| / |B|: the share of the cycle's length made of generated (gap-filling) segments
  // (Eq. 1's numerator over the perimeter). A real object's outline is mostly detected edges.
  double gap_share = 1.0;
  // The share of points sampled along the boundary with a grey-level step across it of at least
  // the edge detector's own threshold. Low when the cycle crosses flat image (an occluder's
  // shadow, a blank frame, a cycle closed through empty space).
  double edge_support = 0.0;
  // shape_distance to the last confident boundary: an occluder or clutter glued to the object
  // changes the shape even when the area stays within the similarity gate.
  double shape_change = 0.0;
  // How far the centroid moved since the previous frame, over the square root of the area (in
  // object sizes): a jump to another cycle.
  double jump = 0.0;
  // Not a feature of the confidence: the mean grey level just inside the boundary (-1 unknown),
  // which a re-found object must roughly keep (a textureless object's level).
  double inside_level = -1.0;
};

// confidence = 1 / (1 + exp(-(bias + sum of weight * feature))). The defaults come from
// bench/fit_confidence.py on rendered occlusion, gap and clutter scenes (not on the dataset).
struct ConfidenceModel {
  double bias = 9.37;
  double gap_share = -20.6;
  double edge_support = 0.0;  // fitted with the wrong sign: left out
  double shape_change = -43.16;
  double jump = 0.0;  // fitted with the wrong sign: left out

  double operator()(const BoundaryEvidence& evidence) const;
};

// The evidence of `boundary` (its cycle's generated length `gap_length`) against the previous
// frame's boundary and the last confident one's descriptor. `gray` is the part of the frame at
// `gray_origin` (frame coordinates) the tracker looked at; samples outside it count as
// unsupported. `min_step`: the grey-level step an edge needs (the detector's threshold).
// `descriptor`, when given, gets shape_descriptor(boundary), which the shape change needs anyway.
BoundaryEvidence measure_evidence(const Polygon& boundary, double gap_length,
                                  const Polygon& previous, const ShapeDescriptor& reference,
                                  const cv::Mat& gray, cv::Point gray_origin, double min_step,
                                  ShapeDescriptor* descriptor = nullptr);

struct EdgeSamples {
  double support = 0.0;        // BoundaryEvidence::edge_support
  double inside_level = -1.0;  // BoundaryEvidence::inside_level
};

// Grey levels 2 px either side of points sampled along the boundary (8-bit `gray` at
// `gray_origin`): the share of samples with a step of at least `min_step`, and the mean inside.
EdgeSamples sample_edges(const Polygon& boundary, const cv::Mat& gray, cv::Point gray_origin,
                         double min_step);

}  // namespace scbt
