#include <algorithm>
#include <cstring>
#include <opencv2/imgproc.hpp>

#include "scbt/lines/edlines.h"
#include "scbt/lines/edlines_maps.h"
#include "scbt/lines/gaussian_5x5.h"
#include "scbt/lines/pixel_loop.h"

namespace scbt {

using namespace edlines_maps;  // NOLINT(build/namespaces): the map codes the stages share

namespace {

// One row of Sobel gradients: magnitude |gx| + |gy| into g, and into d the edge direction of
// the pixels at or above `threshold` (0 below), for columns 1 .. w - 2.
SCBT_PIXEL_LOOP void sobel_row(const std::uint8_t* __restrict above,
                               const std::uint8_t* __restrict row,
                               const std::uint8_t* __restrict below, std::uint16_t* __restrict g,
                               std::uint8_t* __restrict d, int w, std::int16_t threshold) {
  for_each_pixel(1, w - 1, [=](int c) {
    // Sobel: gx = (C + 2E + H) - (A + 2D + F), gy = (F + 2G + H) - (A + 2B + C) with
    // A B C / D x E / F G H around the pixel.
    // 16-bit arithmetic (|gx|, |gy| <= 1020) so that the loop vectorises 8 (16) pixels wide.
    const std::int16_t diag1 = static_cast<std::int16_t>(below[c + 1] - above[c - 1]);  // H-A
    const std::int16_t diag2 = static_cast<std::int16_t>(above[c + 1] - below[c - 1]);  // C-F
    const std::int16_t sx =
        static_cast<std::int16_t>(diag1 + diag2 + 2 * (row[c + 1] - row[c - 1]));
    const std::int16_t sy = static_cast<std::int16_t>(diag1 - diag2 + 2 * (below[c] - above[c]));
    const std::int16_t gx = static_cast<std::int16_t>(sx < 0 ? -sx : sx);
    const std::int16_t gy = static_cast<std::int16_t>(sy < 0 ? -sy : sy);
    const std::int16_t sum = static_cast<std::int16_t>(gx + gy);
    g[c] = static_cast<std::uint16_t>(sum);
    d[c] = sum < threshold ? 0 : (gx >= gy ? kVertical : kHorizontal);
  });
}

// Clears the directions of the pixels outside the band (mask 0), columns 1 .. w - 2.
SCBT_PIXEL_LOOP void mask_row(std::uint8_t* __restrict d, const std::uint8_t* __restrict m, int w) {
  for_each_pixel(1, w - 1,
                 [=](int c) { d[c] = static_cast<std::uint8_t>(d[c] & (m[c] ? 0xFF : 0)); });
}

// Marks the anchors of one row in e, columns 2 .. w - 3, branch-free (vectorised): an anchor
// exceeds both neighbours across its edge direction by `threshold`. Gradients fit in 16 bits
// (at most 2040).
SCBT_PIXEL_LOOP void anchor_row(const std::uint16_t* __restrict up,
                                const std::uint16_t* __restrict g,
                                const std::uint16_t* __restrict down,
                                const std::uint8_t* __restrict d, std::uint8_t* __restrict e, int w,
                                std::int16_t threshold) {
  for_each_pixel(2, w - 2, [=](int c) {
    const std::int16_t value = static_cast<std::int16_t>(g[c]);
    const std::int16_t left = static_cast<std::int16_t>(g[c - 1]);
    const std::int16_t right = static_cast<std::int16_t>(g[c + 1]);
    const std::int16_t above = static_cast<std::int16_t>(up[c]);
    const std::int16_t below = static_cast<std::int16_t>(down[c]);
    const bool vertical = d[c] == kVertical;
    const std::int16_t before = vertical ? left : above;
    const std::int16_t after = vertical ? right : below;
    const int anchor = static_cast<int>(d[c] != 0) &
                       static_cast<int>(static_cast<std::int16_t>(value - before) >= threshold) &
                       static_cast<int>(static_cast<std::int16_t>(value - after) >= threshold);
    e[c] = static_cast<std::uint8_t>(anchor * kAnchor);
  });
}

}  // namespace

// Smoothing, gradients and edge directions (cleared outside the band). With `near_band` (the
// band as spans), only where the edge walks and anchors of the band can read them: walks and
// anchors read gradients and directions up to one pixel from the band, the gradients read the
// smoothed image one pixel further (two from the band), and a smoothed row reads the
// horizontally filtered rows two above and below (four rows from the band). The blocks of
// kCoverBlock columns within two columns and four rows of the band cover all of it; values
// elsewhere are stale or unspecified and never read. Otherwise on the whole window, with
// the band, if any, as a mask.
void EdLines::smooth_and_gradient(const cv::Mat& gray, const cv::Mat& band_mask,
                                  const RowSpans* near_band) {
  const int w = width_, h = height_;
  const size_t n = static_cast<size_t>(w) * h;
  if (near_band != nullptr) {
    cover_with_blocks(*near_band, 2, 4, &blocks_);
    // A buffer kept across windows of changing size (a cv::Mat would reallocate each time).
    if (smooth_pixels_.size() < n) smooth_pixels_.resize(n);
    smooth_ = cv::Mat(h, w, CV_8UC1, smooth_pixels_.data());
    gaussian_blur_5x5(gray, blocks_, &smooth_);
  } else if (params_.sigma < 1.0) {
    gray.copyTo(smooth_);
  } else if (params_.sigma == 1.0) {
    gaussian_blur_5x5(gray, &smooth_);
  } else {
    cv::GaussianBlur(gray, smooth_, cv::Size(), params_.sigma, params_.sigma);
  }
  grad_.resize(n);
  dir_.resize(n);
  if (std::max(params_.scan_interval, 1) == 1) {
    edge_.resize(n);
    clear_edge_frame();
  } else {
    edge_.assign(n, 0);
  }
  const int threshold = params_.gradient_threshold;
  const std::int16_t threshold16 = static_cast<std::int16_t>(std::min(threshold, 30000));
  // The frame's border pixels stop every walk.
  const std::uint16_t border = static_cast<std::uint16_t>(std::max(threshold - 1, 0));
  std::fill(grad_.begin(), grad_.begin() + w, border);
  std::fill(grad_.end() - w, grad_.end(), border);
  std::fill(dir_.begin(), dir_.begin() + w, 0);
  std::fill(dir_.end() - w, dir_.end(), 0);
  for (int r = 1; r < h - 1; ++r) {
    const std::uint8_t* above = smooth_.ptr<std::uint8_t>(r - 1);
    const std::uint8_t* row = smooth_.ptr<std::uint8_t>(r);
    const std::uint8_t* below = smooth_.ptr<std::uint8_t>(r + 1);
    std::uint16_t* g = grad_.data() + static_cast<size_t>(r) * w;
    std::uint8_t* d = dir_.data() + static_cast<size_t>(r) * w;
    if (near_band == nullptr) {
      sobel_row(above, row, below, g, d, w, threshold16);
      if (!band_mask.empty()) mask_row(d, band_mask.ptr<std::uint8_t>(r), w);
    } else {
      for (const ColumnSpan* s = blocks_.begin(r); s != blocks_.end(r); ++s) {
        const int from = std::max(s->begin, 1), to = std::min(s->end, w - 1);
        if (from >= to) continue;
        // sobel_row computes columns 1 .. width - 2 of the row it is given.
        const int shift = from - 1;
        sobel_row(above + shift, row + shift, below + shift, g + shift, d + shift, to - from + 2,
                  threshold16);
        int c = from;  // the first column not yet known to be in the band or cleared
        for (const ColumnSpan* b = near_band->begin(r); b != near_band->end(r) && c < to; ++b) {
          if (b->end <= c) continue;
          if (b->begin >= to) break;
          if (b->begin > c) std::memset(d + c, 0, static_cast<size_t>(b->begin - c));
          c = b->end;
        }
        if (c < to) std::memset(d + c, 0, static_cast<size_t>(to - c));
      }
    }
    g[0] = g[w - 1] = border;
    d[0] = d[w - 1] = 0;
  }
}

// find_anchors writes every pixel it scans (rows and columns 2 .. size - 3): only the
// two-pixel frame around them needs clearing, not the whole map.
void EdLines::clear_edge_frame() {
  const int w = width_, h = height_;
  std::fill(edge_.begin(), edge_.begin() + 2 * w, 0);
  std::fill(edge_.end() - 2 * w, edge_.end(), 0);
  for (int r = 2; r < h - 2; ++r) {
    std::uint8_t* e = edge_.data() + static_cast<size_t>(r) * w;
    e[0] = e[1] = e[w - 2] = e[w - 1] = 0;
  }
}

// Appends the anchors marked on columns from .. to - 1 of `row` (left to right), eight columns at
// a time: the non-zero bytes of each eight are found by their bits.
void EdLines::collect_anchors(int row, int from, int to) {
  const std::uint8_t* e = edge_.data() + static_cast<size_t>(row) * width_;
  const int base = row * width_;
  int c = from;
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
  for (; c + 8 <= to; c += 8) {
    std::uint64_t word;
    std::memcpy(&word, e + c, 8);
    while (word != 0) {
      const int at = c + __builtin_ctzll(word) / 8;  // the lowest byte comes first
      if (e[at] == kAnchor) anchors_.push_back(base + at);
      word &= ~(std::uint64_t{0xFF} << (8 * (at - c)));
    }
  }
#endif
  for (; c < to; ++c) {
    if (e[c] == kAnchor) anchors_.push_back(base + c);
  }
}

// Anchors: on the whole window, or only in the blocks near the band (after smooth_and_gradient
// with a band: `near_band`).
void EdLines::find_anchors(bool near_band) {
  const int w = width_, h = height_;
  const int step = std::max(params_.scan_interval, 1);
  const std::int16_t threshold = static_cast<std::int16_t>(params_.anchor_threshold);
  anchors_.clear();
  for (int r = 2; r < h - 2; ++r) {
    const std::uint16_t* g = grad_.data() + static_cast<size_t>(r) * w;
    const std::uint8_t* d = dir_.data() + static_cast<size_t>(r) * w;
    std::uint8_t* e = edge_.data() + static_cast<size_t>(r) * w;
    if (near_band) {
      for (const ColumnSpan* s = blocks_.begin(r); s != blocks_.end(r); ++s) {
        const int from = std::max(s->begin, 2), to = std::min(s->end, w - 2);
        if (from >= to) continue;
        // anchor_row marks columns 2 .. width - 3 of the row it is given.
        const int shift = from - 2;
        anchor_row(g - w + shift, g + shift, g + w + shift, d + shift, e + shift, to - from + 4,
                   threshold);
        collect_anchors(r, from, to);
      }
      continue;
    }
    if (r % step != 0) {  // only every step-th column on this row
      for (int c = step; c < w - 2; c += step) {
        if (d[c] == 0) continue;
        const int across = d[c] == kVertical ? 1 : w;
        if (g[c] - g[c - across] >= threshold && g[c] - g[c + across] >= threshold) e[c] = kAnchor;
      }
    } else {
      anchor_row(g - w, g, g + w, d, e, w, threshold);
    }
    collect_anchors(r, 2, w - 2);
  }
}

// Counting sort by gradient, largest first; ties in raster order.
void EdLines::sort_anchors() {
  int max_grad = 0;
  for (int p : anchors_) max_grad = std::max<int>(max_grad, grad_[p]);
  bucket_.assign(static_cast<size_t>(max_grad) + 2, 0);
  for (int p : anchors_) ++bucket_[max_grad - grad_[p] + 1];
  for (size_t i = 1; i < bucket_.size(); ++i) bucket_[i] += bucket_[i - 1];
  sorted_anchors_.resize(anchors_.size());
  for (int p : anchors_) sorted_anchors_[bucket_[max_grad - grad_[p]]++] = p;
}

}  // namespace scbt
