// A set of pixels of a window stored row by row as sorted, disjoint column spans: the tracker's
// search band (band_mask.h), and the blocks of columns the line detector computes in (edlines.h).
#pragma once

#include <cstdint>
#include <opencv2/core/types.hpp>
#include <vector>

namespace scbt {

struct ColumnSpan {
  int begin, end;  // columns begin .. end - 1
};

class RowSpans {
 public:
  // Starts an empty set on a window of `size` (buffers kept from earlier sets).
  void reset(cv::Size size);
  // Adds columns first .. last of `row` (both inclusive; clipped to the window, nothing if
  // empty after clipping). Overlapping and touching spans merge.
  void add(int row, int first, int last);

  cv::Size size() const { return size_; }
  // The spans of `row`, left to right: [begin(row), end(row)).
  const ColumnSpan* begin(int row) const {
    if (!flat_) flatten();
    return flat_spans_.data() + row_start_[row];
  }
  const ColumnSpan* end(int row) const {
    if (!flat_) flatten();
    return flat_spans_.data() + row_start_[row + 1];
  }
  // The number of pixels in the set.
  long long area() const;

  // Writes 255 on the set's pixels and 0 elsewhere into `mask` (CV_8UC1 of size()).
  void draw(cv::Mat* mask) const;
  // The pixels of `mask` (CV_8UC1) that are not 0.
  void assign_from_mask(const cv::Mat& mask);

 private:
  // Spans grow in a pool as per-row linked lists kept sorted and merged; begin() flattens them
  // once (most rows of a band hold two spans, so a list beats sorting all spans at the end).
  struct Node {
    ColumnSpan span;
    int next;
  };
  void flatten() const;

  cv::Size size_;
  std::vector<int> head_;
  std::vector<Node> pool_;
  mutable bool flat_ = true;
  mutable std::vector<int> row_start_;  // spans of row r: flat_spans_[row_start_[r], [r + 1])
  mutable std::vector<ColumnSpan> flat_spans_;
};

// The blocks of kCoverBlock columns (k kCoverBlock .. (k + 1) kCoverBlock - 1, clipped to the
// window) that hold a pixel at most grow_columns columns and grow_rows rows from one of `spans`
// (the set grown by a rectangle), as spans of `out` (same window), each at least kPixelChunk
// columns long where the window allows: the detector's vectorised row loops then run whole
// chunks (for_each_pixel in pixel_loop.h).
constexpr int kCoverBlock = 8;
void cover_with_blocks(const RowSpans& spans, int grow_columns, int grow_rows, RowSpans* out);

}  // namespace scbt
