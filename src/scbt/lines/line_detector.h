// Straight line segment detection behind one small interface, so that EDLines (the paper's
// choice: our own implementation by default, or OpenCV's EdgeDrawing as "opencv-edlines"), LSD
// and the FastLineDetector can be swapped with an option.
#pragma once

#include <memory>
#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

#include "scbt/geometry/polygon.h"

namespace scbt {

enum class LineDetectorKind {
  // "edlines" (also "scbt-edlines"): our own EDLines (scbt/lines/edlines.h), the default: the
  // same algorithm and parameters as OpenCV's, about 3x faster, no overflow, and detect_near
  // looks only at the band around a boundary.
  kEdLines,
  // "opencv-edlines": OpenCV ximgproc's EdgeDrawing (EDLines), guarded against its heap
  // overflow; the straightforward pipeline's detector in `scbt bench`.
  kOpenCvEdLines,
  kLsd,               // "lsd": OpenCV's LSD
  kFastLineDetector,  // "fld": OpenCV ximgproc's FastLineDetector
};

// Parses "edlines", "scbt-edlines" (the same), "opencv-edlines", "lsd" or "fld"; throws
// std::invalid_argument otherwise.
LineDetectorKind parse_line_detector_kind(const std::string& name);
std::string to_string(LineDetectorKind kind);

struct LineDetectorOptions {
  LineDetectorKind kind = LineDetectorKind::kEdLines;
  // EDLines settings (edlines and opencv-edlines), from Akinlar & Topal's original EDLines: Sobel
  // gradients, gradient threshold 36, anchor threshold 8, anchors scanned on every row.
  int gradient_threshold = 36;
  int anchor_threshold = 8;
  int scan_interval = 1;
  // Gaussian smoothing before gradients (EDLines uses sigma 1).
  double sigma = 1.0;
  // Segments shorter than this (pixels) are dropped; <= 0 lets EDLines derive it from the image
  // size as in the original paper (EDLines' reference code and OpenCV never go below 9).
  double min_line_length = -1.0;
  // EDLines: how far (pixels) an edge pixel may be from the line it extends.
  double line_fit_error = 1.0;
  // Tracking detects only inside the previous boundary's bounding box grown by the filter
  // distance plus `roi_padding` pixels, instead of on the whole frame (EDLines' 5x5 Gaussian and
  // 3x3 Sobel need 3 px; 8 px measured at least as accurate as the whole frame on all six
  // dataset sequences, while single sequences' success rates move by up to 0.04 with a pixel
  // more or less padding, since segments cut by the band's edge differ; docs/performance.md).
  // false: the whole frame (the straightforward pipeline).
  bool crop_to_boundary = true;
  double roi_padding = 8.0;

  // Throws std::invalid_argument naming the first bad value.
  void check() const;
};

class LineDetector {
 public:
  virtual ~LineDetector() = default;
  // `gray` is an 8-bit single-channel image. Segments are in its pixel coordinates.
  virtual std::vector<Segment> detect(const cv::Mat& gray) = 0;
  // Detects on `crop`, a window at `offset` of an image of `full_size`, with the settings the
  // detector would use on the whole image (EDLines' automatic minimum length depends on the image
  // size), and returns segments in the whole image's coordinates. `crop` may be a non-contiguous
  // view. The default shifts the result of detect().
  virtual std::vector<Segment> detect_in(const cv::Mat& crop, cv::Point offset, cv::Size full_size);
  // As detect_in, but only segments near `boundary` (a closed polygon in the whole image's
  // coordinates) are needed: a detector may look only at the pixels within `radius` of it, so
  // that segments farther away may be missing (and segments crossing the band's edge may be cut
  // there). The default ignores the band and calls detect_in; "edlines" restricts its edges
  // to the band. An empty boundary or a radius that is not positive and finite means no band.
  virtual std::vector<Segment> detect_near(const cv::Mat& crop, cv::Point offset,
                                           cv::Size full_size, const Polygon& boundary,
                                           double radius);
  // Whether set_edge_thresholds has an effect (our EDLines).
  virtual bool adapts_thresholds() const { return false; }
  // Replaces the EDLines gradient and anchor thresholds for the next detections.
  virtual void set_edge_thresholds(int /*gradient*/, int /*anchor*/) {}
};

// The part of a `frame_size` image within `margin` pixels of the polygon's bounding box (whole
// pixels, clipped to the image; empty when they do not overlap).
cv::Rect detection_roi(const Polygon& boundary, double margin, cv::Size frame_size);

// The minimum segment length EDLines picks for an image of this size when min_line_length <= 0
// (the number of pixels whose chance alignment has NFA below 1: -logNT / log10(1/8) / 2, with
// logNT = 2 (log10 w + log10 h), rounded).
int edlines_auto_min_line_length(cv::Size size);

std::unique_ptr<LineDetector> make_line_detector(const LineDetectorOptions& options);

// One-shot convenience: detect segments on an 8-bit grey or BGR image.
std::vector<Segment> detect_line_segments(const cv::Mat& image, const LineDetectorOptions& options);

}  // namespace scbt
