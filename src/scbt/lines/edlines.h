// Our own EDLines line segment detector (Akinlar & Topal, "EDLines: A real-time line segment
// detector with a false detection control", Pattern Recognition Letters 2011, on Edge Drawing,
// Topal & Akinlar, JVCIR 2012), written for the tracker's per-frame budget:
//   1. Gaussian smoothing (sigma 1: 5x5 kernel), Sobel gradients, magnitude |gx| + |gy|, and the
//      edge direction per pixel (vertical edge where |gx| >= |gy|, else horizontal);
//   2. anchors: pixels at or above the gradient threshold that exceed both neighbours across the
//      edge direction by the anchor threshold;
//   3. edge drawing: from the anchors in decreasing gradient order, walk along the gradient ridge
//      (to the largest of the three pixels ahead), turning when the edge direction turns; each
//      anchor's walk is a tree of chains whose longest root-to-leaf paths become edge segments;
//   4. lines: least-squares fits on each edge segment, started on min_line_length pixels
//      (RMS error <= 0.5 px) and extended while pixels stay within line_fit_error of the line;
//      collinear neighbouring lines of a segment joined;
//   5. a-contrario validation: a line is kept when its number of gradient-aligned pixels (level
//      line within 22.5 degrees, p = 1/8, on the unsmoothed image) has NFA <= 1, with the number
//      of tests (W H)^2 of the image analysed (the window, when detecting in one: the candidate
//      lines tested are those in it; OpenCV's EdgeDrawing run on the window does the same).
// Steps 1-2 are in edlines_gradient.cc, 3 in edlines_edge_drawing.cc, 4 in edlines_line_fit.cc,
// 5 in edlines_validation.cc. Flat member buffers are reused from call to call; no allocation in
// steady state beyond the output vector's growth. The input may be a window of a larger image (the
// automatic minimum line length then uses the larger image's size) and may be restricted to a band
// (a mask, or spans per row) where edges may start and run, which is how the tracker looks only
// near its previous boundary; with a band, steps 1 and 2 run only in the blocks of columns near it.
#pragma once

#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "scbt/geometry/polygon.h"
#include "scbt/lines/row_spans.h"

namespace scbt {

struct EdLinesParams {
  int gradient_threshold = 36;
  int anchor_threshold = 8;
  int scan_interval = 1;  // anchors are looked for on every scan_interval-th row and column
  double sigma = 1.0;     // Gaussian smoothing; < 1 smooths nothing (as the reference code)
  // Pixels a line needs; <= 0: EDLines' automatic minimum from the whole image's size, which the
  // reference implementation never lets drop below 9.
  int min_line_length = -1;
  double line_fit_error = 1.0;  // max distance (px) of a pixel added while extending a line
  int min_path_length = 10;     // anchor walks with fewer pixels are discarded
  double max_line_gap = 6.0;    // collinear lines of a segment are joined up to this end gap
  double max_join_error = 1.3;  // ... when the shorter's points are this close to the longer
  bool nfa_validation = true;
  // With a band (and sigma 1, scan interval 1): smooth and take gradients only in the blocks of
  // columns near the band, which gives the same segments as the whole window (tested) for less
  // work; false computes them everywhere.
  bool compute_near_band_only = true;
};

// The minimum number of pixels a line needs with `params` in an image of `full_size`.
int edlines_min_line_length(const EdLinesParams& params, cv::Size full_size);

class EdLines {
 public:
  explicit EdLines(const EdLinesParams& params = EdLinesParams());

  // Detects on `gray` (8-bit, single channel, any stride), a window at `offset` of an image of
  // `full_size`, and appends the segments, in the larger image's coordinates (pixel centres at
  // integers), to `out` (cleared first). `band`, when not empty, is a CV_8UC1 mask of gray's size:
  // only its non-zero pixels may be edge pixels. Throws std::invalid_argument for another type.
  void detect(const cv::Mat& gray, cv::Point offset, cv::Size full_size, const cv::Mat& band,
              std::vector<Segment>* out);
  // The same with the band as spans per row (band_spans in band_mask.h; nullptr: no band).
  // With the default smoothing (sigma 1) and scan interval (1), smoothing and gradients are
  // computed only in the blocks of columns within two columns and four rows of the band (all that
  // the edge walks and anchors read), not on the whole window (compute_near_band_only).
  void detect(const cv::Mat& gray, cv::Point offset, cv::Size full_size, const RowSpans* band,
              std::vector<Segment>* out);

  // Replaces the gradient and anchor thresholds for the next detections (per-frame adaptation).
  void set_thresholds(int gradient, int anchor) {
    params_.gradient_threshold = gradient;
    params_.anchor_threshold = anchor;
  }

  // The edge segments (pixel chains, in gray's coordinates) of the last detect(): for tests.
  std::vector<std::vector<cv::Point>> edge_segments() const;

 private:
  struct Chain {
    int dir;
    int len;
    int first;  // index of the first pixel in chain_pixels_
    int children[2];
  };
  struct StackNode {
    int pixel;
    int dir;
    int parent;
  };
  struct Line {
    double a, b;  // v = a + b u, with (u, v) = (x, y), or (y, x) when `invert`
    bool invert;
    double sx, sy, ex, ey;
    int segment;
    int first;  // first pixel index within its edge segment
    int len;    // pixels of the edge segment making it up
  };

  void smooth_and_gradient(const cv::Mat& gray, const cv::Mat& band_mask,
                           const RowSpans* near_band);
  void find_anchors(bool near_band);
  void clear_edge_frame();
  void collect_anchors(int row, int from, int to);
  void sort_anchors();
  void draw_edges();
  void walk_from_anchor(int anchor);
  int longest_chain(int root);
  void append_chain(int chain, bool reversed, int skip_first);
  void close_segment(bool main);
  void fit_lines(int min_length);
  void split_segment(int segment, int min_length);
  void join_collinear_lines();
  bool try_join(Line* l1, const Line& l2) const;
  bool validate(const Line& line, const cv::Mat& gray);
  int min_aligned(int n);

  EdLinesParams params_;
  int width_ = 0, height_ = 0;
  cv::Mat contiguous_, smooth_;
  std::vector<std::uint8_t> smooth_pixels_;  // smooth_'s pixels on the band path, kept across calls
  RowSpans band_from_mask_, blocks_;
  cv::Mat band_mask_;
  std::vector<std::uint16_t> grad_;
  std::vector<std::uint8_t> dir_;
  std::vector<std::uint8_t> edge_;
  std::vector<int> anchors_, sorted_anchors_, bucket_;
  std::vector<Chain> chains_;
  std::vector<StackNode> stack_;
  std::vector<int> chain_pixels_, dfs_, order_, best_, path_;
  // Edge segments: linear pixel indices; segment i is seg_pixels_[seg_start_[i], seg_end_[i]).
  std::vector<int> seg_pixels_, seg_start_, seg_end_;
  int open_begin_ = 0;  // first pixel of the segment being assembled
  std::vector<double> xs_, ys_;
  std::vector<Line> lines_;
  struct RowRange {
    int row, first, last;  // columns first .. last of `row`
  };
  std::vector<RowRange> row_ranges_;  // validate()'s rectangle, row by row
  // NFA: log10 of the number of tests of the current image, and log10 binomial tails (row n
  // starts at tail_start_[n]) kept across calls.
  double log_nt_ = 0.0;
  std::vector<double> log10_tail_;
  std::vector<int> tail_start_;
};

}  // namespace scbt
