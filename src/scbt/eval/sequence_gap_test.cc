#include "scbt/eval/sequence_gap.h"

#include <gtest/gtest.h>

#include <limits>

namespace scbt {
namespace {

TEST(SequenceGapTest, VariantsSitInTheMiddleAndNameThemselves) {
  const SequenceGap grey = SequenceGap::grey(100);
  EXPECT_EQ(grey.start, 50);
  EXPECT_EQ(grey.end(), 80);
  EXPECT_EQ(grey.name(), "grey30");
  EXPECT_TRUE(grey.in_gap(50));
  EXPECT_TRUE(grey.in_gap(79));
  EXPECT_FALSE(grey.in_gap(80));
  EXPECT_FALSE(grey.dropped(60));
  const SequenceGap drop = SequenceGap::drop(200);
  EXPECT_EQ(drop.name(), "jump60");
  EXPECT_TRUE(drop.dropped(100));
  EXPECT_FALSE(drop.dropped(160));
  EXPECT_EQ(SequenceGap().name(), "clean");
  EXPECT_FALSE(SequenceGap().in_gap(0));
  EXPECT_THROW(SequenceGap::drop(120), std::invalid_argument);  // 60 + 60 leaves no 10 after
  EXPECT_THROW(SequenceGap::grey(100, 0), std::invalid_argument);
}

TEST(SequenceGapTest, VariantsStartWhereTheirPositionSays) {
  EXPECT_EQ(SequenceGap::grey(200, 30, 0.2).start, 40);
  EXPECT_EQ(SequenceGap::drop(200, 60, 0.6).start, 120);
  EXPECT_EQ(SequenceGap::grey(200, 30, 0.2).name(), "grey30");
  // Outside (0, 1), or too late for the gap and 10 frames after it.
  EXPECT_THROW(SequenceGap::grey(200, 30, 0.0), std::invalid_argument);
  EXPECT_THROW(SequenceGap::grey(200, 30, 1.5), std::invalid_argument);
  EXPECT_THROW(SequenceGap::drop(200, 60, 0.7), std::invalid_argument);
}

TEST(SequenceGapTest, GreyFramesBecomeUniformOthersStay) {
  const SequenceGap gap = SequenceGap::grey(100);
  cv::Mat frame(4, 4, CV_8UC3, cv::Scalar(10, 20, 30));
  gap.apply(10, &frame);
  EXPECT_EQ(frame.at<cv::Vec3b>(0, 0), cv::Vec3b(10, 20, 30));
  gap.apply(55, &frame);
  EXPECT_EQ(frame.at<cv::Vec3b>(3, 3), cv::Vec3b(128, 128, 128));
}

// Frames 0..99, the gap 50..79: wrong and unsure in the gap, right from frame 83 on except one.
std::vector<LossFrame> gap_run(const SequenceGap& gap) {
  std::vector<LossFrame> frames;
  for (int k = 0; k < 100; ++k) {
    if (gap.dropped(k)) continue;
    LossFrame f;
    f.index = k;
    const bool right = k < 50 || (k >= 83 && k != 90);
    f.e_al = right ? 2.0 : std::numeric_limits<double>::infinity();
    f.confidence = right ? 0.9 : (k == 90 ? 0.95 : 0.1);  // frame 90: confidently wrong
    f.tracking = right || k == 90;
    frames.push_back(f);
  }
  return frames;
}

TEST(SequenceGapTest, DelaySuccessAfterAndAucOfAGapRun) {
  for (const SequenceGap& gap :
       {SequenceGap::grey(100), SequenceGap{GapVariantKind::kDrop, 50, 30}}) {
    const LossScores s = score_loss(gap_run(gap), gap);
    EXPECT_EQ(s.scored, 70);  // the gap's 30 frames are not scored
    EXPECT_EQ(s.wrong, 4);    // 80, 81, 82 and 90
    EXPECT_EQ(s.reacquire_delay, 3);
    ASSERT_TRUE(s.success_after.has_value());
    EXPECT_NEAR(*s.success_after, 16.0 / 17.0, 1e-12);  // 83..99, one wrong
    // 3 wrong frames rank above every right one, frame 90 below all of them: (3 * 66) / (4 * 66).
    ASSERT_TRUE(s.auc.has_value());
    EXPECT_NEAR(*s.auc, 0.75, 1e-12);
  }
}

TEST(SequenceGapTest, NeverReacquiredHasNoDelayAndNoSuccessAfter) {
  const SequenceGap gap = SequenceGap::grey(100);
  std::vector<LossFrame> frames;
  for (int k = 0; k < 100; ++k) {
    frames.push_back({k, k < 50 ? 1.0 : 50.0, k < 50 ? 0.9 : 0.0, k < 50});
  }
  const LossScores s = score_loss(frames, gap);
  EXPECT_EQ(s.reacquire_delay, -1);
  EXPECT_FALSE(s.success_after.has_value());
  EXPECT_NEAR(s.auc.value(), 1.0, 1e-12);
  // A clean run: no delay; an AUC needs both kinds of frame.
  EXPECT_FALSE(score_loss({{0, 1.0, 0.9, true}, {1, 2.0, 0.8, true}}, SequenceGap()).auc);
}

}  // namespace
}  // namespace scbt
