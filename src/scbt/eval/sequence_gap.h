// Gap variants of a sequence, for measuring loss handling on real video (issue 18): the object is
// taken away for a while, either by frames replaced with uniform grey (nothing to see) or by
// frames dropped (the video jumps ahead, the object reappears elsewhere), and the tracker must say
// so and find it again. Also the scores of such a run: how fast it re-acquires, how well it
// tracks after that, and how well its confidence separates wrong frames from right ones.
#pragma once

#include <opencv2/core/mat.hpp>
#include <optional>
#include <string>
#include <vector>

namespace scbt {

enum class GapVariantKind {
  kNone,
  kGrey,  // frames replaced by uniform grey (128): tracked, not scored
  kDrop,  // frames dropped: neither tracked nor scored
};

struct SequenceGap {
  GapVariantKind kind = GapVariantKind::kNone;
  int start = 0;   // 0-based index of the first frame of the gap
  int length = 0;  // frames in the gap

  // The two variants, the gap starting at `position` (a fraction of the sequence; the middle by
  // default) of a sequence of `frames` frames: 30 grey frames (1 s at 30 fps) and 60 dropped
  // frames (a 2 s jump). Throws std::invalid_argument when the sequence is too short to hold the
  // gap there and 10 frames after it, or the position is not in (0, 1).
  static SequenceGap grey(int frames, int length = 30, double position = 0.5);
  static SequenceGap drop(int frames, int length = 60, double position = 0.5);

  bool in_gap(int index) const {
    return kind != GapVariantKind::kNone && index >= start && index < start + length;
  }
  bool dropped(int index) const { return kind == GapVariantKind::kDrop && in_gap(index); }
  // Replaces a grey frame's pixels; other frames are left as they are.
  void apply(int index, cv::Mat* frame) const;
  int end() const { return start + length; }  // the first frame after the gap
  // "grey30", "jump60", "clean": a folder and column name.
  std::string name() const;
};

// The name of the variant of this kind ("clean", "grey30", "jump60"), as
// SequenceGap::grey / drop with their default lengths name it.
std::string sequence_gap_name(GapVariantKind kind);

// One frame of a run, as the scores need it.
struct LossFrame {
  int index = 0;          // 0-based in the original sequence
  double e_al = 0.0;      // +infinity for a failure
  double confidence = 0;  // the tracker's, in [0, 1]
  bool tracking = false;  // the tracker's state was `tracking`
};

struct LossScores {
  // ROC AUC of (1 - confidence) against E_AL >= wrong_px, over the scored frames (the gap's
  // frames excluded); nullopt without a wrong or without a right frame.
  std::optional<double> auc;
  int scored = 0;  // frames scored
  int wrong = 0;   // of those, E_AL >= wrong_px
  // Frames from the end of the gap to the first right (E_AL < wrong_px) frame in state
  // `tracking`; -1 when that never happens (or there is no gap).
  int reacquire_delay = -1;
  // Success rate at wrong_px over the frames after re-acquisition (from the re-acquired frame on);
  // nullopt when never re-acquired.
  std::optional<double> success_after;
  int after = 0;  // frames success_after is over
};

// `frames` in sequence order, the gap's frames already left out or flagged by `gap`.
LossScores score_loss(const std::vector<LossFrame>& frames, const SequenceGap& gap,
                      double wrong_px = 10.0);

}  // namespace scbt
