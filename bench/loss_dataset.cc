// Loss handling on the dataset: per sequence, the confidence's ROC AUC (E_AL >= 10 px positive)
// on the clean sequence, and the re-acquisition delay and success after two gap variants: 30
// frames replaced by uniform grey (1 s at 30 fps), and 60 frames dropped (a 2 s jump). The gap
// starts at the middle of the sequence; gaps and scores are eval/sequence_gap's, as in
// `scbt eval --gaps` (S@10 after = from the re-acquired frame on).
//
//   build/bench/scbt_loss_dataset [--trace clean|grey|jump [--dump DIR]]
//       [--retry-weak-frames true|false] DATASET_DIR [SEQUENCE...]
#include <cmath>
#include <cstdio>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "scbt/eval/alignment_error.h"
#include "scbt/eval/dataset.h"
#include "scbt/eval/roc.h"
#include "scbt/eval/sequence_gap.h"
#include "scbt/geometry/polygon_io.h"
#include "scbt/io/frame_source.h"
#include "scbt/tracker/tracker.h"

namespace scbt {
namespace {

constexpr double kWrongPx = 10.0;

enum class Variant { kClean, kGrey, kJump };

struct Run {
  int frames = 0;
  int wrong = 0;
  int states[3] = {0, 0, 0};
  double auc = -1.0;
  double success_10 = 0.0;  // clean: all frames; gaps: frames from re-acquisition on
  int delay = -1;           // frames from the end of the gap to the first right tracked frame
  double ms_mean = 0.0;
  std::vector<double> scores;  // 1 - confidence of every frame outside the gap
  std::vector<bool> is_wrong;  // E_AL >= 10 px, per score
};

// Draws `polygon` closed onto `image`.
void draw_polygon(cv::Mat* image, const Polygon& polygon, const cv::Scalar& colour) {
  std::vector<cv::Point> points;
  for (const Point& p : polygon) points.emplace_back(cvRound(p.x), cvRound(p.y));
  cv::polylines(*image, points, true, colour, 1, cv::LINE_AA);
}

// trace: print one line per frame (state, confidence, evidence, error) to stderr. dump: a folder
// to write the frames around the gap's end into, the truth green and the boundary by state.
Run run_variant(const DatasetSequence& sequence, Variant variant, const TrackerOptions& options,
                bool trace = false, const std::string& dump = "") {
  std::vector<Polygon> truth;
  for (const std::string& line : read_text_lines(sequence.ground_truth)) {
    truth.push_back(parse_polygon_line(line));
  }
  std::unique_ptr<FrameSource> source = open_frame_source(sequence.frames);
  const int total = std::min<int>(source->frame_count(), truth.size());
  const SequenceGap gap = variant == Variant::kGrey   ? SequenceGap::grey(total)
                          : variant == Variant::kJump ? SequenceGap::drop(total)
                                                      : SequenceGap();
  Tracker tracker(options);
  Run run;
  std::vector<LossFrame> frames;
  double ms = 0.0;
  cv::Mat frame;
  for (int k = 0; k < total && source->read(&frame); ++k) {
    if (k == 0) {
      tracker.init(frame, truth[0]);
      continue;
    }
    const bool in_gap = gap.in_gap(k);
    if (gap.dropped(k)) continue;
    gap.apply(k, &frame);
    const TrackResult r = tracker.track(frame);
    ms += r.total_ms();
    ++run.frames;
    ++run.states[static_cast<int>(r.state)];
    const double error = in_gap ? -1.0 : alignment_error(r.boundary, truth[k], frame.size());
    if (trace) {
      std::fprintf(stderr,
                   "frame %d%s state %s conf %.3f gap %.3f shape %.3f support %.2f jump %.3f "
                   "level %.0f held %d reacq %d E_AL %.2f at (%.0f, %.0f) size %.0f truth (%.0f, "
                   "%.0f) size %.0f\n",
                   k + 1, in_gap ? " (gap)" : "", to_string(r.state).c_str(), r.confidence,
                   r.evidence.gap_share, r.evidence.shape_change, r.evidence.edge_support,
                   r.evidence.jump, r.evidence.inside_level, r.held ? 1 : 0, r.reacquired ? 1 : 0,
                   error, centroid(r.boundary).x, centroid(r.boundary).y,
                   std::sqrt(area(r.boundary)), centroid(truth[k]).x, centroid(truth[k]).y,
                   std::sqrt(area(truth[k])));
    }
    if (!dump.empty() && gap.kind != GapVariantKind::kNone && k >= gap.start - 5 &&
        k < gap.end() + 40) {
      cv::Mat image = frame.channels() == 1 ? cv::Mat() : frame.clone();
      if (image.empty()) cv::cvtColor(frame, image, cv::COLOR_GRAY2BGR);
      draw_polygon(&image, truth[k], cv::Scalar(0, 255, 0));
      const cv::Scalar colour = r.state == TrackState::kTracking    ? cv::Scalar(255, 128, 0)
                                : r.state == TrackState::kUncertain ? cv::Scalar(0, 200, 255)
                                                                    : cv::Scalar(0, 0, 255);
      draw_polygon(&image, r.boundary, colour);
      cv::imwrite(dump + "/" + sequence.name + "_" + std::to_string(k + 1) + ".png", image);
    }
    frames.push_back({k, error, r.confidence, r.state == TrackState::kTracking});
    if (in_gap) continue;
    run.scores.push_back(1.0 - r.confidence);
    run.is_wrong.push_back(!(error < kWrongPx));
  }
  const LossScores loss = score_loss(frames, gap, kWrongPx);
  run.wrong = loss.wrong;
  run.auc = loss.auc.value_or(-1.0);
  run.delay = loss.reacquire_delay;
  if (variant == Variant::kClean) {
    run.success_10 = loss.scored > 0 ? 1.0 - static_cast<double>(loss.wrong) / loss.scored : 0.0;
  } else {
    run.success_10 = loss.success_after.value_or(0.0);
  }
  run.ms_mean = run.frames > 0 ? ms / run.frames : 0.0;
  return run;
}

}  // namespace
}  // namespace scbt

int main(int argc, char** argv) {
  using namespace scbt;
  std::vector<std::string> args(argv + 1, argv + argc);
  // --trace clean|grey|jump: one line per frame of that variant to stderr, and only that variant.
  // --dump DIR: with --trace, the frames around the gap's end as images into DIR.
  // --retry-weak-frames true|false: AdaptiveThresholdOptions::retry_weak_frames (default: its
  // default).
  std::string trace, dump, retry;
  for (size_t i = 0; i + 1 < args.size();) {
    if (args[i] == "--trace" || args[i] == "--dump" || args[i] == "--retry-weak-frames") {
      (args[i] == "--trace" ? trace : args[i] == "--dump" ? dump : retry) = args[i + 1];
      args.erase(args.begin() + i, args.begin() + i + 2);
    } else {
      ++i;
    }
  }
  if (args.empty() || !(trace.empty() || trace == "clean" || trace == "grey" || trace == "jump") ||
      !(retry.empty() || retry == "true" || retry == "false")) {
    std::fprintf(
        stderr,
        "usage: %s [--trace clean|grey|jump [--dump DIR]] [--retry-weak-frames true|false] "
        "DATASET_DIR [SEQUENCE...]\n",
        argv[0]);
    return 2;
  }
  TrackerOptions options;
  if (!retry.empty()) options.adaptive_thresholds.retry_weak_frames = retry == "true";
  const std::vector<std::string> names(args.begin() + 1, args.end());
  const std::vector<DatasetSequence> sequences = select_dataset_sequences(args[0], names);
  if (!trace.empty()) {
    const Variant variant = trace == "clean"  ? Variant::kClean
                            : trace == "grey" ? Variant::kGrey
                                              : Variant::kJump;
    for (const DatasetSequence& sequence : sequences) {
      const Run run = run_variant(sequence, variant, options, /*trace=*/true, dump);
      std::printf("%s %s: delay %d, S@10 %.3f, AUC %.3f\n", sequence.name.c_str(), trace.c_str(),
                  run.delay, run.success_10, run.auc);
    }
    return 0;
  }
  std::printf(
      "| sequence | frames | E_AL>=10 | AUC | S@10 | tracking/uncertain/lost | ms | grey: delay, "
      "S@10 after re-acq. | jump: delay, S@10 after re-acq. "
      "|\n|---|---:|---:|---:|---:|---|---:|---|---|\n");
  std::vector<double> clean_scores, all_scores;
  std::vector<bool> clean_wrong, all_wrong;
  auto pool = [](const Run& run, std::vector<double>* scores, std::vector<bool>* wrong) {
    scores->insert(scores->end(), run.scores.begin(), run.scores.end());
    wrong->insert(wrong->end(), run.is_wrong.begin(), run.is_wrong.end());
  };
  for (const DatasetSequence& sequence : sequences) {
    const Run clean = run_variant(sequence, Variant::kClean, options);
    const Run grey = run_variant(sequence, Variant::kGrey, options);
    const Run jump = run_variant(sequence, Variant::kJump, options);
    std::printf("| %s | %d | %d | %.3f | %.3f | %d/%d/%d | %.3f | %d, %.3f | %d, %.3f |\n",
                sequence.name.c_str(), clean.frames, clean.wrong, clean.auc, clean.success_10,
                clean.states[0], clean.states[1], clean.states[2], clean.ms_mean, grey.delay,
                grey.success_10, jump.delay, jump.success_10);
    std::fflush(stdout);
    pool(clean, &clean_scores, &clean_wrong);
    for (const Run* run : {&clean, &grey, &jump}) pool(*run, &all_scores, &all_wrong);
  }
  std::printf("\npooled AUC: clean %.3f, clean + gap variants %.3f\n",
              roc_auc(clean_scores, clean_wrong).value_or(-1.0),
              roc_auc(all_scores, all_wrong).value_or(-1.0));
  return 0;
}
