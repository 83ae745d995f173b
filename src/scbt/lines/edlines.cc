#include "scbt/lines/edlines.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "scbt/lines/gaussian_5x5.h"
#include "scbt/lines/pixel_loop.h"

namespace scbt {
namespace {

// Edge direction of a pixel at or above the gradient threshold (0: not an edge candidate).
constexpr std::uint8_t kHorizontal = 1;  // |gx| < |gy|: the edge runs left-right
constexpr std::uint8_t kVertical = 2;    // |gx| >= |gy|: the edge runs up-down

// Edge map states.
constexpr std::uint8_t kAnchor = 1;
constexpr std::uint8_t kEdge = 2;

// Walking directions; the first two share child slot 0, the last two slot 1.
enum WalkDir { kLeft = 0, kUp = 1, kRight = 2, kDown = 3 };

constexpr double kInitialFitError = 0.5;  // RMS error of a line's first min_length pixels
constexpr int kMaxOutliers = 5;           // consecutive far pixels that end a line
constexpr int kAcceptWithoutTest = 80;    // lines of this many pixels are valid as they are
constexpr int kRectTestUpTo = 25;         // lines up to this many pixels: rectangle test only
// cos(22.5 deg): a pixel is aligned when its level line is within 22.5 degrees of the line.
const double kAlignedCos = std::cos(22.5 * M_PI / 180.0);
const double kAlignedCos2 = kAlignedCos * kAlignedCos;
constexpr double kAlignedProbability = 0.125;

bool adjacent(int p, int q, int width) {
  return std::abs(p / width - q / width) <= 1 && std::abs(p % width - q % width) <= 1;
}

// Least-squares line v = a + b u through (u_i, v_i); RMS orthogonal distance in `error`.
void fit_uv(const double* u, const double* v, int n, double* a, double* b, double* error) {
  double mu = 0.0, mv = 0.0;
  for (int i = 0; i < n; ++i) mu += u[i], mv += v[i];
  mu /= n;
  mv /= n;
  double suu = 0.0, suv = 0.0;
  for (int i = 0; i < n; ++i) {
    suu += (u[i] - mu) * (u[i] - mu);
    suv += (u[i] - mu) * (v[i] - mv);
  }
  *b = suu > 0.0 ? suv / suu : 0.0;
  *a = mv - *b * mu;
  if (error != nullptr) {
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
      const double r = v[i] - *a - *b * u[i];
      sum += r * r;
    }
    *error = std::sqrt(sum / (n * (1.0 + *b * *b)));
  }
}

double line_distance(double x, double y, double a, double b, bool invert) {
  const double u = invert ? y : x, v = invert ? x : y;
  return std::abs(v - a - b * u) / std::sqrt(1.0 + b * b);
}

void closest_point(double x, double y, double a, double b, bool invert, double* px, double* py) {
  const double u = invert ? y : x, v = invert ? x : y;
  const double t = (u + (v - a) * b) / (1.0 + b * b);
  const double pu = t, pv = a + b * t;
  *px = invert ? pv : pu;
  *py = invert ? pu : pv;
}

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

int edlines_min_line_length(const EdLinesParams& params, cv::Size full_size) {
  if (params.min_line_length > 0) return params.min_line_length;
  const double log_nt =
      2.0 * (std::log10(std::max(1, full_size.width)) + std::log10(std::max(1, full_size.height)));
  const int automatic = static_cast<int>(std::round(-log_nt / std::log10(0.125) * 0.5));
  return std::max(automatic, 9);
}

EdLines::EdLines(const EdLinesParams& params) : params_(params) {}

void EdLines::detect(const cv::Mat& gray, cv::Point offset, cv::Size full_size, const cv::Mat& band,
                     std::vector<Segment>* out) {
  const RowSpans* spans = nullptr;
  if (!gray.empty() && !band.empty()) {
    if (band.type() != CV_8UC1 || band.size() != gray.size()) {
      throw std::invalid_argument("EdLines band mask must be CV_8UC1 of the image's size");
    }
    band_from_mask_.assign_from_mask(band);
    spans = &band_from_mask_;
  }
  detect(gray, offset, full_size, spans, out);
}

void EdLines::detect(const cv::Mat& gray, cv::Point offset, cv::Size full_size,
                     const RowSpans* band, std::vector<Segment>* out) {
  out->clear();
  if (gray.empty()) return;
  if (gray.type() != CV_8UC1) {
    throw std::invalid_argument("EdLines needs an 8-bit single-channel image, got type " +
                                std::to_string(gray.type()));
  }
  if (band != nullptr && band->size() != gray.size()) {
    throw std::invalid_argument("EdLines band spans must be on the image's window");
  }
  width_ = gray.cols;
  height_ = gray.rows;
  seg_pixels_.clear();
  seg_start_.clear();
  seg_end_.clear();
  open_begin_ = 0;
  lines_.clear();
  if (width_ < 5 || height_ < 5) return;  // no interior pixel can be an anchor

  // OpenCV's GaussianBlur of a view into a larger image reads the pixels around it (and rounds
  // differently): for other sigmas than EDLines' 1 (gaussian_blur_5x5, which reads the view's
  // pixels only), work on a copy, so that the result depends on the window's pixels only.
  const cv::Mat* input = &gray;
  if (!gray.isContinuous() && params_.sigma != 1.0) {
    gray.copyTo(contiguous_);
    input = &contiguous_;
  }
  if (band != nullptr && params_.compute_near_band_only && params_.sigma == 1.0 &&
      std::max(params_.scan_interval, 1) == 1) {
    smooth_and_gradient(*input, cv::Mat(), band);
    find_anchors(true);
  } else {
    if (band != nullptr) band->draw(&band_mask_);
    smooth_and_gradient(*input, band != nullptr ? band_mask_ : cv::Mat(), nullptr);
    find_anchors(false);
  }
  sort_anchors();
  draw_edges();
  fit_lines(edlines_min_line_length(params_, full_size));
  join_collinear_lines();

  const double log_nt = 2.0 * (std::log10(std::max(1, width_)) + std::log10(std::max(1, height_)));
  log_nt_ = log_nt;
  out->reserve(lines_.size());
  for (const Line& line : lines_) {
    if (params_.nfa_validation && !validate(line, *input)) continue;
    out->push_back({Point(line.sx + offset.x, line.sy + offset.y),
                    Point(line.ex + offset.x, line.ey + offset.y)});
  }
}

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

void EdLines::draw_edges() {
  for (int anchor : sorted_anchors_) {
    if (edge_[anchor] != kAnchor) continue;  // already on an edge, or cleared
    walk_from_anchor(anchor);
  }
}

void EdLines::walk_from_anchor(int anchor) {
  const int w = width_;
  chains_.clear();
  stack_.clear();
  chain_pixels_.clear();
  chains_.push_back({-1, 0, 0, {-1, -1}});
  if (dir_[anchor] == kVertical) {
    stack_.push_back({anchor, kDown, 0});
    stack_.push_back({anchor, kUp, 0});
  } else {
    stack_.push_back({anchor, kRight, 0});
    stack_.push_back({anchor, kLeft, 0});
  }
  int shared_starts = 0;  // start pixels counted twice
  while (!stack_.empty()) {
    const StackNode node = stack_.back();
    stack_.pop_back();
    if (edge_[node.pixel] != kEdge) ++shared_starts;
    const bool horizontal = node.dir == kLeft || node.dir == kRight;
    const std::uint8_t want = horizontal ? kHorizontal : kVertical;
    // Ahead, and the two diagonal pixels ahead ("a" before "c" when tied edges exist).
    int ahead, side_a, side_c;
    switch (node.dir) {
      case kLeft:
        ahead = -1, side_a = -w, side_c = w;
        break;
      case kRight:
        ahead = 1, side_a = w, side_c = -w;
        break;
      case kUp:
        ahead = -w, side_a = -1, side_c = 1;
        break;
      default:
        ahead = w, side_a = 1, side_c = -1;
        break;
    }
    const int side = horizontal ? w : 1;  // across the edge
    Chain chain{node.dir, 1, static_cast<int>(chain_pixels_.size()), {-1, -1}};
    int p = node.pixel;
    chain_pixels_.push_back(p);
    bool turned = false;
    while (true) {
      if (dir_[p] != want) {
        turned = true;
        break;
      }
      edge_[p] = kEdge;
      if (edge_[p - side] == kAnchor) edge_[p - side] = 0;  // anchors beside the edge
      if (edge_[p + side] == kAnchor) edge_[p + side] = 0;
      const int straight = p + ahead, first = straight + side_a, second = straight + side_c;
      if (edge_[straight] != 0) {
        p = straight;
      } else if (edge_[first] != 0) {
        p = first;
      } else if (edge_[second] != 0) {
        p = second;
      } else {
        // Follow the ridge: the largest gradient of the three ahead; on ties the straight one,
        // then the one on the plus side (row below, or column to the right).
        const int minus = straight - side, plus = straight + side;
        const int gs = grad_[straight], gm = grad_[minus], gp = grad_[plus];
        if (gm > gs) {
          p = gm > gp ? minus : plus;
        } else {
          p = gp > gs ? plus : straight;
        }
      }
      if (edge_[p] == kEdge || dir_[p] == 0) break;
      chain_pixels_.push_back(p);
      ++chain.len;
    }
    const int index = static_cast<int>(chains_.size());
    if (turned) {
      // p turns the edge: two chains go on from it across this one; p is their first pixel.
      if (horizontal) {
        stack_.push_back({p, kDown, index});
        stack_.push_back({p, kUp, index});
      } else {
        stack_.push_back({p, kRight, index});
        stack_.push_back({p, kLeft, index});
      }
      chain_pixels_.pop_back();
      --chain.len;
    }
    chains_.push_back(chain);
    chains_[node.parent].children[node.dir <= kUp ? 0 : 1] = index;
  }

  const int walked = static_cast<int>(chain_pixels_.size());
  if (walked - shared_starts < params_.min_path_length) {
    for (int q : chain_pixels_) edge_[q] = 0;
    return;
  }

  // One segment: the longest path on the second side reversed, then the first side's.
  if (longest_chain(chains_[0].children[1]) > 0) {
    path_.clear();
    for (int k = chains_[0].children[1]; k >= 0;) {
      path_.push_back(k);
      k = chains_[k].children[0] >= 0 ? chains_[k].children[0] : chains_[k].children[1];
    }
    for (int i = static_cast<int>(path_.size()) - 1; i >= 0; --i) append_chain(path_[i], true, 0);
  }
  if (longest_chain(chains_[0].children[0]) > 1) {
    path_.clear();
    for (int k = chains_[0].children[0]; k >= 0;) {
      path_.push_back(k);
      k = chains_[k].children[0] >= 0 ? chains_[k].children[0] : chains_[k].children[1];
    }
    for (size_t i = 0; i < path_.size(); ++i) append_chain(path_[i], false, i == 0 ? 1 : 0);
  }
  close_segment(true);

  // Other long branches become segments of their own.
  const int count = static_cast<int>(chains_.size());
  for (int k = 2; k < count; ++k) {
    if (chains_[k].len < 2) continue;
    if (longest_chain(k) < params_.min_path_length) continue;
    path_.clear();
    for (int j = k; j >= 0;) {
      path_.push_back(j);
      j = chains_[j].children[0] >= 0 ? chains_[j].children[0] : chains_[j].children[1];
    }
    for (int j : path_) append_chain(j, false, 0);
    close_segment(false);
  }
}

// Length of the longest root-to-leaf path under `root` (0 for none); prunes every node to its
// longer child so that following children walks that path.
int EdLines::longest_chain(int root) {
  if (root < 0 || chains_[root].len == 0) return 0;
  best_.resize(chains_.size());
  order_.clear();
  dfs_.clear();
  dfs_.push_back(root);
  while (!dfs_.empty()) {
    const int k = dfs_.back();
    dfs_.pop_back();
    order_.push_back(k);
    for (int c : chains_[k].children) {
      if (c >= 0 && chains_[c].len > 0) dfs_.push_back(c);
    }
  }
  for (auto it = order_.rbegin(); it != order_.rend(); ++it) {
    Chain& chain = chains_[*it];
    int lengths[2] = {0, 0};
    for (int s = 0; s < 2; ++s) {
      const int c = chain.children[s];
      if (c >= 0 && chains_[c].len > 0) lengths[s] = best_[c];
    }
    if (lengths[0] >= lengths[1]) {
      chain.children[1] = -1;
      if (lengths[0] == 0) chain.children[0] = -1;
    } else {
      chain.children[0] = -1;
    }
    best_[*it] = chain.len + std::max(lengths[0], lengths[1]);
  }
  return best_[root];
}

// Appends a chain's pixels (reversed or not, skipping `skip_first` of them) to the open segment,
// dropping pixels that would make a corner with it, and marks the chain copied.
void EdLines::append_chain(int chain_index, bool reversed, int skip_first) {
  Chain& chain = chains_[chain_index];
  const int n = chain.len - skip_first;
  if (n <= 0) {
    chain.len = 0;
    return;
  }
  const int* pixels = chain_pixels_.data() + chain.first;
  auto at = [&](int i) { return reversed ? pixels[chain.len - 1 - i] : pixels[skip_first + i]; };
  const size_t begin = static_cast<size_t>(open_begin_);
  // Pixels of the open segment before its last one that touch the new first pixel make the last
  // one a detour: drop it.
  const int head = at(0);
  while (seg_pixels_.size() >= begin + 2 &&
         adjacent(head, seg_pixels_[seg_pixels_.size() - 2], width_)) {
    seg_pixels_.pop_back();
  }
  int start = 0;
  if (n > 1 && seg_pixels_.size() > begin && adjacent(at(1), seg_pixels_.back(), width_)) start = 1;
  for (int i = start; i < n; ++i) seg_pixels_.push_back(at(i));
  chain.len = 0;
}

// Ends the open segment; an anchor's main segment drops its first pixel when its second one
// touches the last (a closed edge).
void EdLines::close_segment(bool main) {
  const int end = static_cast<int>(seg_pixels_.size());
  int begin = open_begin_;
  if (main && end - begin >= 2 && adjacent(seg_pixels_[begin + 1], seg_pixels_[end - 1], width_)) {
    ++begin;
  }
  if (end > begin) {
    seg_start_.push_back(begin);
    seg_end_.push_back(end);
  }
  open_begin_ = end;
}

void EdLines::fit_lines(int min_length) {
  for (size_t s = 0; s < seg_start_.size(); ++s) split_segment(static_cast<int>(s), min_length);
}

// Splits one edge segment into lines: fit min_length pixels (sliding on by one pixel while the
// fit is poor), then extend while pixels stay near the line, refitting on every extension.
void EdLines::split_segment(int segment, int min_length) {
  const int begin = seg_start_[segment];
  const int total = seg_end_[segment] - begin;
  if (total < min_length) return;
  xs_.resize(total);
  ys_.resize(total);
  for (int i = 0; i < total; ++i) {
    xs_[i] = seg_pixels_[begin + i] % width_;
    ys_[i] = seg_pixels_[begin + i] / width_;
  }
  int first = 0;  // first pixel not yet in a line
  while (total - first >= min_length) {
    // A good initial fit.
    double a = 0.0, b = 0.0, error = 0.0;
    bool invert = false, found = false;
    for (; total - first >= min_length; ++first) {
      const double* x = xs_.data() + first;
      const double* y = ys_.data() + first;
      double mx = 0.0, my = 0.0;
      for (int i = 0; i < min_length; ++i) mx += x[i], my += y[i];
      mx /= min_length;
      my /= min_length;
      double vx = 0.0, vy = 0.0;
      for (int i = 0; i < min_length; ++i) {
        vx += (x[i] - mx) * (x[i] - mx);
        vy += (y[i] - my) * (y[i] - my);
      }
      invert = vx < vy;  // steep: x = a + b y
      fit_uv(invert ? y : x, invert ? x : y, min_length, &a, &b, &error);
      if (error <= kInitialFitError) {
        found = true;
        break;
      }
    }
    if (!found) return;
    const double* x = xs_.data() + first;
    const double* y = ys_.data() + first;
    const int n = total - first;
    int len = min_length;  // pixels fitted so far (from x[0])
    int last_good = min_length - 1;
    int index = min_length;
    // As in the reference implementation, a fit that reaches the end of the segment without a
    // pixel left to extend it to makes no line.
    if (index >= n) return;
    while (index < n) {
      const int start = index;
      int good = 0, bad = 0;
      for (; index < n; ++index) {
        if (line_distance(x[index], y[index], a, b, invert) <= params_.line_fit_error) {
          last_good = index;
          ++good;
          bad = 0;
        } else if (++bad >= kMaxOutliers) {
          break;
        }
      }
      if (good < 2) break;
      len += last_good - start + 1;
      fit_uv(invert ? y : x, invert ? x : y, len, &a, &b, nullptr);
      index = last_good + 1;
    }
    // Ends: the first and last pixels near the line, projected on it.
    int s = 0;
    while (s < last_good && line_distance(x[s], y[s], a, b, invert) > params_.line_fit_error) ++s;
    int e = last_good;
    while (e > s && line_distance(x[e], y[e], a, b, invert) > params_.line_fit_error) --e;
    Line line{a, b, invert, 0, 0, 0, 0, segment, first + s, e - s + 1};
    closest_point(x[s], y[s], a, b, invert, &line.sx, &line.sy);
    closest_point(x[e], y[e], a, b, invert, &line.ex, &line.ey);
    if (line.sx != line.ex || line.sy != line.ey) lines_.push_back(line);
    first += e + 1;
  }
}

// Joins consecutive collinear lines of each edge segment, and its last line with its first.
void EdLines::join_collinear_lines() {
  size_t kept = 0;
  for (size_t i = 0; i < lines_.size();) {
    const int segment = lines_[i].segment;
    const size_t first = kept;
    lines_[kept++] = lines_[i++];
    for (; i < lines_.size() && lines_[i].segment == segment; ++i) {
      if (!try_join(&lines_[kept - 1], lines_[i])) lines_[kept++] = lines_[i];
    }
    if (kept - 1 > first && try_join(&lines_[first], lines_[kept - 1])) --kept;
  }
  lines_.resize(kept);
}

bool EdLines::try_join(Line* l1, const Line& l2) const {
  const Point s1(l1->sx, l1->sy), e1(l1->ex, l1->ey), s2(l2.sx, l2.sy), e2(l2.ex, l2.ey);
  const double gap =
      std::min({cv::norm(s1 - s2), cv::norm(s1 - e2), cv::norm(e1 - s2), cv::norm(e1 - e2)});
  if (gap > params_.max_line_gap) return false;
  const bool first_longer = cv::norm(s1 - e1) > cv::norm(s2 - e2);
  const Line& longer = first_longer ? *l1 : l2;
  const Line& shorter = first_longer ? l2 : *l1;
  const double error = (line_distance(shorter.sx, shorter.sy, longer.a, longer.b, longer.invert) +
                        line_distance((shorter.sx + shorter.ex) / 2, (shorter.sy + shorter.ey) / 2,
                                      longer.a, longer.b, longer.invert) +
                        line_distance(shorter.ex, shorter.ey, longer.a, longer.b, longer.invert)) /
                       3.0;
  if (error > params_.max_join_error) return false;
  // The joined line spans the two ends farthest apart (in L1 distance).
  const Point candidates[4][2] = {{s1, s2}, {s1, e2}, {e1, s2}, {e1, e2}};
  int pick = 0;
  double widest = -1.0;
  for (int k = 0; k < 4; ++k) {
    const Point d = candidates[k][0] - candidates[k][1];
    const double l1_distance = std::abs(d.x) + std::abs(d.y);
    if (l1_distance > widest) widest = l1_distance, pick = k;
  }
  // Oriented as the reference implementation does: s1 -> s2, s1 -> e2, s2 -> e1, e1 -> e2.
  const Point from = pick == 2 ? s2 : candidates[pick][0];
  const Point to = pick == 2 ? e1 : candidates[pick][1];
  l1->sx = from.x, l1->sy = from.y, l1->ex = to.x, l1->ey = to.y;
  if (l1->first + l1->len + 5 >= l2.first) {
    l1->len += l2.len;
  } else if (l2.len > l1->len) {
    l1->first = l2.first;
    l1->len = l2.len;
  }
  // The line through the new ends.
  const double dx = to.x - from.x, dy = to.y - from.y;
  l1->invert = std::abs(dx) < std::abs(dy);
  const double du = l1->invert ? dy : dx, dv = l1->invert ? dx : dy;
  const double u0 = l1->invert ? from.y : from.x, v0 = l1->invert ? from.x : from.y;
  l1->b = du != 0.0 ? dv / du : 0.0;
  l1->a = v0 - l1->b * u0;
  return true;
}

int EdLines::min_aligned(int n) {
  // Row n of the table: log10 of the binomial tail P[at least k of n aligned], k = 0..n, computed
  // once (from k = n down, adding terms in log space) and kept for every later call.
  while (static_cast<int>(tail_start_.size()) <= n) {
    const int m = static_cast<int>(tail_start_.size());
    tail_start_.push_back(static_cast<int>(log10_tail_.size()));
    log10_tail_.resize(log10_tail_.size() + m + 1);
    double* row = log10_tail_.data() + tail_start_.back();
    const double p = kAlignedProbability;
    double term = m * std::log(p);  // ln P[exactly m aligned]
    double tail = term;
    row[m] = tail / std::log(10.0);
    for (int k = m; k >= 1; --k) {
      term += std::log(static_cast<double>(k) / (m - k + 1)) + std::log((1.0 - p) / p);
      tail = std::max(tail, term) + std::log1p(std::exp(-std::abs(tail - term)));
      row[k - 1] = std::min(tail / std::log(10.0), 0.0);
    }
  }
  // The fewest aligned pixels with NFA = NT * tail <= 1 (n + 1: none).
  const double* row = log10_tail_.data() + tail_start_[n];
  int lo = 0, hi = n + 1;
  while (lo < hi) {
    const int mid = (lo + hi) / 2;
    if (log_nt_ + row[mid] <= 0.0) {
      hi = mid;
    } else {
      lo = mid + 1;
    }
  }
  return lo;
}

// A-contrario test of a line: count the pixels whose level line (on the unsmoothed image) is
// aligned with it, first along the line's own edge pixels (longer lines), then in the width-2
// rectangle around the line.
bool EdLines::validate(const Line& line, const cv::Mat& gray) {
  if (line.len >= kAcceptWithoutTest) return true;
  const double dx = line.ex - line.sx, dy = line.ey - line.sy;
  const double length = std::sqrt(dx * dx + dy * dy);
  if (length <= 0.0) return false;
  const double ux = dx / length, uy = dy / length;
  auto aligned_at = [&](int r, int c) {
    const std::uint8_t* above = gray.ptr<std::uint8_t>(r - 1);
    const std::uint8_t* row = gray.ptr<std::uint8_t>(r);
    const std::uint8_t* below = gray.ptr<std::uint8_t>(r + 1);
    // Prewitt-like 3x3 differences.
    const int gx =
        (above[c + 1] - above[c - 1]) + (row[c + 1] - row[c - 1]) + (below[c + 1] - below[c - 1]);
    const int gy =
        (below[c - 1] - above[c - 1]) + (below[c] - above[c]) + (below[c + 1] - above[c + 1]);
    // A pixel without gradient has level-line angle 0 in the reference implementation (its
    // atan2(0, 0) = 0), so it counts as aligned with lines within 22.5 degrees of horizontal.
    if (gx == 0 && gy == 0) return std::abs(ux) >= kAlignedCos;
    // The level line runs along (-gy, gx); aligned when within 22.5 degrees of the line (mod pi).
    const double along = -gy * ux + gx * uy;
    return along * along >= kAlignedCos2 * (static_cast<double>(gx) * gx + gy * gy);
  };
  auto inside = [&](int r, int c) { return r > 0 && r < height_ - 1 && c > 0 && c < width_ - 1; };

  // Both tests know how many pixels they look at before looking, so each stops as soon as the
  // aligned ones reach the number needed, or can no longer reach it (same answer, fewer pixels).
  if (line.len > kRectTestUpTo) {
    const int begin = seg_start_[line.segment] + line.first;
    const int end = std::min(begin + line.len, seg_end_[line.segment]);
    int count = 0;
    for (int i = begin; i < end; ++i) {
      count += inside(seg_pixels_[i] / width_, seg_pixels_[i] % width_) ? 1 : 0;
    }
    if (count > 0) {
      const int needed = min_aligned(count);
      int aligned = 0, left = count;
      for (int i = begin; i < end && aligned < needed && aligned + left >= needed; ++i) {
        const int r = seg_pixels_[i] / width_, c = seg_pixels_[i] % width_;
        if (!inside(r, c)) continue;
        --left;
        aligned += aligned_at(r, c) ? 1 : 0;
      }
      if (aligned >= needed) return true;
    }
  }
  // Rectangle of width 2 centred on the line: pixel centres p with 0 <= (p - s).u <= length and
  // |(p - s) x u| <= 1.
  int count = 0;
  row_ranges_.clear();
  const int r0 = std::max(1, static_cast<int>(std::floor(std::min(line.sy, line.ey) - 1.0)));
  const int r1 =
      std::min(height_ - 2, static_cast<int>(std::ceil(std::max(line.sy, line.ey) + 1.0)));
  for (int r = r0; r <= r1; ++r) {
    // x range where both constraints hold on this row: each is linear in x.
    double lo = -1e18, hi = 1e18;
    auto clip = [&](double coef, double constant, double min_value, double max_value) {
      // min_value <= coef * x + constant <= max_value
      if (std::abs(coef) < 1e-12) {
        if (constant < min_value || constant > max_value) lo = 1.0, hi = 0.0;
        return;
      }
      double a = (min_value - constant) / coef, b = (max_value - constant) / coef;
      if (a > b) std::swap(a, b);
      lo = std::max(lo, a);
      hi = std::min(hi, b);
    };
    const double ry = r - line.sy;
    clip(ux, -line.sx * ux + ry * uy, 0.0, length);  // along
    clip(-uy, line.sx * uy + ry * ux, -1.0, 1.0);    // across: (p - s) x u = px*uy - py*ux
    // Rows and columns are clipped to the interior, where every pixel has its 3x3 neighbours.
    const int c0 = std::max(1, static_cast<int>(std::ceil(lo - 1e-9)));
    const int c1 = std::min(width_ - 2, static_cast<int>(std::floor(hi + 1e-9)));
    if (c0 > c1) continue;
    row_ranges_.push_back({r, c0, c1});
    count += c1 - c0 + 1;
  }
  if (count == 0) return false;
  const int needed = min_aligned(count);
  int aligned = 0, left = count;
  for (const RowRange& range : row_ranges_) {
    for (int c = range.first; c <= range.last; ++c) {
      if (aligned >= needed || aligned + left < needed) return aligned >= needed;
      --left;
      aligned += aligned_at(range.row, c) ? 1 : 0;
    }
  }
  return aligned >= needed;
}

std::vector<std::vector<cv::Point>> EdLines::edge_segments() const {
  std::vector<std::vector<cv::Point>> segments;
  for (size_t s = 0; s < seg_start_.size(); ++s) {
    std::vector<cv::Point>& points = segments.emplace_back();
    for (int i = seg_start_[s]; i < seg_end_[s]; ++i) {
      points.emplace_back(seg_pixels_[i] % width_, seg_pixels_[i] / width_);
    }
  }
  return segments;
}

}  // namespace scbt
