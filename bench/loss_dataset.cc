// Loss handling on the dataset: per sequence, the confidence's ROC AUC (E_AL >= 10 px positive)
// on the clean sequence, and the re-acquisition delay and success after two gap variants: 30
// frames replaced by uniform grey (1 s at 30 fps), and 60 frames dropped (a 2 s jump). The gap
// starts at the middle of the sequence.
//
//   build/bench/scbt_loss_dataset DATASET_DIR [SEQUENCE...]
#include <cstdio>
#include <string>
#include <vector>

#include "scbt/eval/alignment_error.h"
#include "scbt/eval/dataset.h"
#include "scbt/eval/roc.h"
#include "scbt/geometry/polygon_io.h"
#include "scbt/io/frame_source.h"
#include "scbt/tracker/tracker.h"

namespace scbt {
namespace {

constexpr double kWrongPx = 10.0;
constexpr int kGreyFrames = 30;
constexpr int kDroppedFrames = 60;

enum class Variant { kClean, kGrey, kJump };

struct Run {
  int frames = 0;
  int wrong = 0;
  int states[3] = {0, 0, 0};
  double auc = -1.0;
  double success_10 = 0.0;  // clean: all frames; gaps: frames after the gap
  int delay = -1;           // frames from the end of the gap to the first right tracked frame
  double ms_mean = 0.0;
};

Run run_variant(const DatasetSequence& sequence, Variant variant) {
  std::vector<Polygon> truth;
  for (const std::string& line : read_text_lines(sequence.ground_truth)) {
    truth.push_back(parse_polygon_line(line));
  }
  std::unique_ptr<FrameSource> source = open_frame_source(sequence.frames);
  const int total = std::min<int>(source->frame_count(), truth.size());
  const int gap_start = total / 2;
  const int gap_frames = variant == Variant::kGrey ? kGreyFrames : kDroppedFrames;
  const int gap_end = gap_start + gap_frames;  // first frame index after the gap
  Tracker tracker;
  Run run;
  std::vector<double> scores;
  std::vector<bool> wrong;
  int after = 0, after_right = 0;
  double ms = 0.0;
  cv::Mat frame;
  for (int k = 0; k < total && source->read(&frame); ++k) {
    if (k == 0) {
      tracker.init(frame, truth[0]);
      continue;
    }
    const bool in_gap = variant != Variant::kClean && k >= gap_start && k < gap_end;
    if (in_gap && variant == Variant::kJump) continue;
    if (in_gap) frame.setTo(cv::Scalar::all(128));
    const TrackResult r = tracker.track(frame);
    ms += r.total_ms();
    ++run.frames;
    ++run.states[static_cast<int>(r.state)];
    if (in_gap) continue;
    const double error = alignment_error(r.boundary, truth[k], frame.size());
    const bool is_wrong = !(error < kWrongPx);
    run.wrong += is_wrong ? 1 : 0;
    scores.push_back(1.0 - r.confidence);
    wrong.push_back(is_wrong);
    if (variant == Variant::kClean || k >= gap_end) {
      ++after;
      after_right += is_wrong ? 0 : 1;
      if (variant != Variant::kClean && run.delay < 0 && !is_wrong &&
          r.state == TrackState::kTracking) {
        run.delay = k - gap_end;
      }
    }
  }
  run.auc = roc_auc(scores, wrong).value_or(-1.0);
  run.success_10 = after > 0 ? static_cast<double>(after_right) / after : 0.0;
  run.ms_mean = run.frames > 0 ? ms / run.frames : 0.0;
  return run;
}

}  // namespace
}  // namespace scbt

int main(int argc, char** argv) {
  using namespace scbt;
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s DATASET_DIR [SEQUENCE...]\n", argv[0]);
    return 2;
  }
  const std::vector<std::string> names(argv + 2, argv + argc);
  std::printf(
      "| sequence | frames | E_AL>=10 | AUC | S@10 | tracking/uncertain/lost | ms | grey: delay, "
      "S@10 after | jump: delay, S@10 after |\n|---|---:|---:|---:|---:|---|---:|---|---|\n");
  for (const DatasetSequence& sequence : select_dataset_sequences(argv[1], names)) {
    const Run clean = run_variant(sequence, Variant::kClean);
    const Run grey = run_variant(sequence, Variant::kGrey);
    const Run jump = run_variant(sequence, Variant::kJump);
    std::printf("| %s | %d | %d | %.3f | %.3f | %d/%d/%d | %.3f | %d, %.3f | %d, %.3f |\n",
                sequence.name.c_str(), clean.frames, clean.wrong, clean.auc, clean.success_10,
                clean.states[0], clean.states[1], clean.states[2], clean.ms_mean, grey.delay,
                grey.success_10, jump.delay, jump.success_10);
    std::fflush(stdout);
  }
  return 0;
}
