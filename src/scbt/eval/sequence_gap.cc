#include "scbt/eval/sequence_gap.h"

#include <stdexcept>

#include "scbt/eval/roc.h"

namespace scbt {
namespace {

// The gap starts at `position` of the sequence; at least 10 frames must remain after it to
// measure anything.
SequenceGap gap_at(GapVariantKind kind, int frames, int length, double position) {
  if (length < 1) throw std::invalid_argument("a gap needs at least one frame");
  if (!(position > 0.0 && position < 1.0)) {
    throw std::invalid_argument("a gap's position must be in (0, 1) of the sequence, got " +
                                std::to_string(position));
  }
  SequenceGap gap;
  gap.kind = kind;
  gap.start = static_cast<int>(frames * position);
  gap.length = length;
  if (gap.start < 1 || gap.end() + 10 > frames) {
    throw std::invalid_argument("a sequence of " + std::to_string(frames) +
                                " frames is too short for a gap of " + std::to_string(length) +
                                " frames from frame " + std::to_string(gap.start + 1) +
                                " and 10 frames after it");
  }
  return gap;
}

}  // namespace

SequenceGap SequenceGap::grey(int frames, int length, double position) {
  return gap_at(GapVariantKind::kGrey, frames, length, position);
}

SequenceGap SequenceGap::drop(int frames, int length, double position) {
  return gap_at(GapVariantKind::kDrop, frames, length, position);
}

void SequenceGap::apply(int index, cv::Mat* frame) const {
  if (kind == GapVariantKind::kGrey && in_gap(index)) frame->setTo(cv::Scalar::all(128));
}

std::string SequenceGap::name() const {
  switch (kind) {
    case GapVariantKind::kNone:
      return "clean";
    case GapVariantKind::kGrey:
      return "grey" + std::to_string(length);
    case GapVariantKind::kDrop:
      return "jump" + std::to_string(length);
  }
  return "unknown";
}

std::string sequence_gap_name(GapVariantKind kind) {
  // Only the kind and the length make the name; any sequence long enough gives the same.
  constexpr int kLongEnough = 1000;
  switch (kind) {
    case GapVariantKind::kNone:
      return SequenceGap().name();
    case GapVariantKind::kGrey:
      return SequenceGap::grey(kLongEnough).name();
    case GapVariantKind::kDrop:
      return SequenceGap::drop(kLongEnough).name();
  }
  return "unknown";
}

LossScores score_loss(const std::vector<LossFrame>& frames, const SequenceGap& gap,
                      double wrong_px) {
  LossScores scores;
  std::vector<double> doubt;
  std::vector<bool> wrong;
  int after = 0, after_right = 0;
  for (const LossFrame& f : frames) {
    if (gap.in_gap(f.index)) continue;  // nothing to see, or not shown at all
    const bool is_wrong = !(f.e_al < wrong_px);
    ++scores.scored;
    scores.wrong += is_wrong ? 1 : 0;
    doubt.push_back(1.0 - f.confidence);
    wrong.push_back(is_wrong);
    if (gap.kind == GapVariantKind::kNone || f.index < gap.end()) continue;
    if (scores.reacquire_delay < 0 && !is_wrong && f.tracking) {
      scores.reacquire_delay = f.index - gap.end();
    }
    if (scores.reacquire_delay >= 0) {
      ++after;
      after_right += is_wrong ? 0 : 1;
    }
  }
  scores.auc = roc_auc(doubt, wrong);
  scores.after = after;
  if (after > 0) scores.success_after = static_cast<double>(after_right) / after;
  return scores;
}

}  // namespace scbt
