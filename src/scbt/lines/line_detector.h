// Straight line segment detection behind one small interface, so that EDLines (the paper's
// choice), LSD and the FastLineDetector can be swapped with an option.
#pragma once

#include <memory>
#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

#include "scbt/geometry/polygon.h"

namespace scbt {

enum class LineDetectorKind { kEdLines, kLsd, kFastLineDetector };

// Parses "edlines", "lsd" or "fld"; throws std::invalid_argument otherwise.
LineDetectorKind parse_line_detector_kind(const std::string& name);
std::string to_string(LineDetectorKind kind);

struct LineDetectorOptions {
  LineDetectorKind kind = LineDetectorKind::kEdLines;
  // EDLines settings, from Akinlar & Topal's original EDLines: Sobel gradients, gradient
  // threshold 36, anchor threshold 8, anchors scanned on every row.
  int gradient_threshold = 36;
  int anchor_threshold = 8;
  int scan_interval = 1;
  // Gaussian smoothing before gradients (EDLines uses sigma 1).
  double sigma = 1.0;
  // Segments shorter than this (pixels) are dropped; <= 0 lets EDLines derive it from the image
  // size as in the original paper.
  double min_line_length = -1.0;
  // Maximum mean squared distance of an edge pixel to its fitted line (pixels^2).
  double line_fit_error = 1.0;

  // Throws std::invalid_argument naming the first bad value.
  void check() const;
};

class LineDetector {
 public:
  virtual ~LineDetector() = default;
  // `gray` is an 8-bit single-channel image. Segments are in its pixel coordinates.
  virtual std::vector<Segment> detect(const cv::Mat& gray) = 0;
};

std::unique_ptr<LineDetector> make_line_detector(const LineDetectorOptions& options);

// One-shot convenience: detect segments on an 8-bit grey or BGR image.
std::vector<Segment> detect_line_segments(const cv::Mat& image, const LineDetectorOptions& options);

}  // namespace scbt
