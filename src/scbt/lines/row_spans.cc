#include "scbt/lines/row_spans.h"

#include <algorithm>
#include <cstring>
#include <opencv2/core/mat.hpp>
#include <stdexcept>

#include "scbt/lines/pixel_loop.h"

namespace scbt {

void RowSpans::reset(cv::Size size) {
  size_ = cv::Size(std::max(size.width, 0), std::max(size.height, 0));
  head_.assign(size_.height, -1);
  pool_.clear();
  flat_ = false;
}

void RowSpans::add(int row, int first, int last) {
  if (row < 0 || row >= size_.height) return;
  first = std::max(first, 0);
  last = std::min(last, size_.width - 1);
  if (first > last) return;
  flat_ = false;
  const int b = first, e = last + 1;
  int previous = -1, at = head_[row];
  while (at >= 0 && pool_[at].span.end < b) previous = at, at = pool_[at].next;
  if (at < 0 || pool_[at].span.begin > e) {  // between previous and at, touching neither
    const int added = static_cast<int>(pool_.size());
    pool_.push_back({{b, e}, at});
    (previous < 0 ? head_[row] : pool_[previous].next) = added;
    return;
  }
  ColumnSpan& merged = pool_[at].span;
  merged.begin = std::min(merged.begin, b);
  merged.end = std::max(merged.end, e);
  int next = pool_[at].next;
  while (next >= 0 && pool_[next].span.begin <= merged.end) {
    merged.end = std::max(merged.end, pool_[next].span.end);
    next = pool_[next].next;
  }
  pool_[at].next = next;
}

void RowSpans::flatten() const {
  row_start_.resize(static_cast<size_t>(size_.height) + 1);
  flat_spans_.clear();
  for (int r = 0; r < size_.height; ++r) {
    row_start_[r] = static_cast<int>(flat_spans_.size());
    for (int k = head_[r]; k >= 0; k = pool_[k].next) flat_spans_.push_back(pool_[k].span);
  }
  row_start_[size_.height] = static_cast<int>(flat_spans_.size());
  flat_ = true;
}

long long RowSpans::area() const {
  long long total = 0;
  for (int r = 0; r < size_.height; ++r) {
    for (const ColumnSpan* s = begin(r); s != end(r); ++s) total += s->end - s->begin;
  }
  return total;
}

void RowSpans::draw(cv::Mat* mask) const {
  mask->create(size_, CV_8UC1);
  mask->setTo(0);
  for (int r = 0; r < size_.height; ++r) {
    std::uint8_t* row = mask->ptr<std::uint8_t>(r);
    for (const ColumnSpan* s = begin(r); s != end(r); ++s) {
      std::memset(row + s->begin, 255, static_cast<size_t>(s->end - s->begin));
    }
  }
}

void RowSpans::assign_from_mask(const cv::Mat& mask) {
  if (mask.type() != CV_8UC1) throw std::invalid_argument("RowSpans mask must be CV_8UC1");
  reset(mask.size());
  for (int r = 0; r < mask.rows; ++r) {
    const std::uint8_t* row = mask.ptr<std::uint8_t>(r);
    for (int c = 0; c < mask.cols;) {
      if (row[c] == 0) {
        ++c;
        continue;
      }
      const int first = c;
      while (c < mask.cols && row[c] != 0) ++c;
      add(r, first, c - 1);
    }
  }
}

void cover_with_blocks(const RowSpans& spans, int grow_columns, int grow_rows, RowSpans* out) {
  constexpr int kBlock = kCoverBlock;
  // Spans of whole chunks of the row loops where the window allows (for_each_pixel).
  constexpr int kMinBlocks = kPixelChunk / kBlock;
  static_assert(kPixelChunk % kBlock == 0, "a chunk is whole blocks");
  const cv::Size size = spans.size();
  out->reset(size);
  if (size.width == 0 || size.height == 0) return;
  grow_columns = std::max(grow_columns, 0);
  grow_rows = std::max(grow_rows, 0);
  const int num_blocks = (size.width + kBlock - 1) / kBlock;
  const int words = (num_blocks + 63) / 64;
  // Per row, a bit per block: first the blocks each row's own spans reach (grown sideways), then
  // OR-ed over the rows within grow_rows above and below, one row at a time.
  thread_local std::vector<std::uint64_t> own, grown;
  own.assign(static_cast<size_t>(size.height) * words, 0);
  grown.resize(words);
  for (int r = 0; r < size.height; ++r) {
    std::uint64_t* bits = own.data() + static_cast<size_t>(r) * words;
    for (const ColumnSpan* s = spans.begin(r); s != spans.end(r); ++s) {
      const int first = std::max(s->begin - grow_columns, 0) / kBlock;
      const int last = std::min(s->end - 1 + grow_columns, size.width - 1) / kBlock;
      for (int k = first / 64; k <= last / 64; ++k) {
        // Bits max(first, 64 k) .. min(last, 64 k + 63) of word k.
        const int low = std::max(first - 64 * k, 0), high = std::min(last - 64 * k, 63);
        bits[k] |= (~std::uint64_t{0} >> (63 - high)) & (~std::uint64_t{0} << low);
      }
    }
  }
  for (int r = 0; r < size.height; ++r) {
    std::uint64_t* bits = grown.data();
    std::fill(grown.begin(), grown.end(), 0);
    const int from = std::max(r - grow_rows, 0), to = std::min(r + grow_rows, size.height - 1);
    if (words == 1) {  // windows up to 1024 columns: no loop over words
      std::uint64_t any = 0;
      for (int q = from; q <= to; ++q) any |= own[q];
      bits[0] = any;
    } else {
      for (int q = from; q <= to; ++q) {
        const std::uint64_t* source = own.data() + static_cast<size_t>(q) * words;
        for (int k = 0; k < words; ++k) bits[k] |= source[k];
      }
    }
    for (int k = 0; k < words; ++k) {
      // Each run of set bits is a span (runs across words merge in add).
      for (std::uint64_t word = bits[k]; word != 0;) {
        const int start = __builtin_ctzll(word);
        const std::uint64_t rest = ~(word >> start);
        const int length = rest == 0 ? 64 - start : __builtin_ctzll(rest);
        int first = 64 * k + start, last = first + length - 1;
        if (last - first + 1 < kMinBlocks) {  // grown to the right, then to the left
          last = std::min(num_blocks - 1, first + kMinBlocks - 1);
          first = std::max(0, last - kMinBlocks + 1);
        }
        out->add(r, first * kBlock, std::min((last + 1) * kBlock, size.width) - 1);
        word = start + length >= 64 ? 0 : word & (~std::uint64_t{0} << (start + length));
      }
    }
  }
}

}  // namespace scbt
