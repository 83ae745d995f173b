// RowSpans against a pixel-by-pixel reference: adds merge into sorted, disjoint, non-touching
// spans; masks convert both ways; cover_with_blocks covers the grown set with whole blocks.
#include "scbt/lines/row_spans.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <random>
#include <stdexcept>

namespace scbt {
namespace {

// Random runs on every row, some off the window or empty, as RowSpans and as a mask.
void random_set(std::mt19937* rng, cv::Size size, RowSpans* spans, cv::Mat* mask) {
  spans->reset(size);
  *mask = cv::Mat::zeros(size, CV_8UC1);
  std::uniform_int_distribution<int> count(0, 6), column(-20, size.width + 20),
      length(-3, size.width / 3);
  for (int r = 0; r < size.height; ++r) {
    for (int k = count(*rng); k > 0; --k) {
      const int first = column(*rng), last = first + length(*rng);
      spans->add(r, first, last);
      for (int c = std::max(first, 0); c <= std::min(last, size.width - 1); ++c) {
        mask->at<uchar>(r, c) = 255;
      }
    }
  }
}

void expect_well_formed(const RowSpans& spans) {
  for (int r = 0; r < spans.size().height; ++r) {
    int previous_end = -1;
    for (const ColumnSpan* s = spans.begin(r); s != spans.end(r); ++s) {
      EXPECT_LT(s->begin, s->end);
      EXPECT_GT(s->begin, previous_end) << "row " << r << ": spans overlap or touch";
      EXPECT_GE(s->begin, 0);
      EXPECT_LE(s->end, spans.size().width);
      previous_end = s->end;
    }
  }
}

TEST(RowSpans, AddsMergeIntoTheSetOfPixelsAdded) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 50; ++trial) {
    const cv::Size size(1 + trial * 7 % 90, 1 + trial % 13);
    RowSpans spans;
    cv::Mat expected, drawn;
    random_set(&rng, size, &spans, &expected);
    expect_well_formed(spans);
    spans.draw(&drawn);
    EXPECT_EQ(cv::countNonZero(drawn != expected), 0) << "trial " << trial;
    EXPECT_EQ(spans.area(), cv::countNonZero(expected));

    RowSpans again;
    again.assign_from_mask(expected);
    again.draw(&drawn);
    EXPECT_EQ(cv::countNonZero(drawn != expected), 0);
  }
}

TEST(RowSpans, RejectsAMaskOfAnotherType) {
  RowSpans spans;
  EXPECT_THROW(spans.assign_from_mask(cv::Mat::zeros(3, 3, CV_16UC1)), std::invalid_argument);
}

TEST(RowSpans, BlocksCoverTheGrownSetWithWholeBlocksOnly) {
  constexpr int kBlock = kCoverBlock;
  std::mt19937 rng(5);
  for (int trial = 0; trial < 40; ++trial) {
    const cv::Size size(20 + trial * 37 % 1500, 3 + trial % 40);  // some wider than 64 blocks
    RowSpans spans, blocks;
    cv::Mat mask;
    random_set(&rng, size, &spans, &mask);
    // Thin the set out so that the grown set leaves blocks empty.
    for (int r = 0; r < size.height; ++r) {
      if (r % 5 != 0) mask.row(r).setTo(0);
    }
    spans.assign_from_mask(mask);
    const int grow_columns = trial % 6, grow_rows = trial % 4;
    cover_with_blocks(spans, grow_columns, grow_rows, &blocks);
    expect_well_formed(blocks);
    cv::Mat grown, covered;
    cv::dilate(mask, grown, cv::Mat::ones(2 * grow_rows + 1, 2 * grow_columns + 1, CV_8UC1));
    blocks.draw(&covered);
    EXPECT_EQ(cv::countNonZero(grown & ~covered), 0) << "trial " << trial << ": not covered";
    for (int r = 0; r < size.height; ++r) {
      for (const ColumnSpan* s = blocks.begin(r); s != blocks.end(r); ++s) {
        EXPECT_EQ(s->begin % kBlock, 0);
        EXPECT_TRUE(s->end % kBlock == 0 || s->end == size.width);
        EXPECT_TRUE(s->end - s->begin > 32 - kBlock || s->end - s->begin == size.width)
            << "a span shorter than 32 columns";
        // Every block touches the grown set, or is among those added to reach 32 columns.
        for (int b = s->begin; b < s->end; b += kBlock) {
          const int from = std::max(b - 32, 0), to = std::min(b + 32 + kBlock, size.width);
          EXPECT_GT(cv::countNonZero(grown.row(r).colRange(from, to)), 0)
              << "trial " << trial << " row " << r << " block at " << b;
        }
      }
    }
  }
}

}  // namespace
}  // namespace scbt
