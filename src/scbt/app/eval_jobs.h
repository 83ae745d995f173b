// The jobs of `scbt eval`: one per (tracker, sequence) pair, each running a tracker over the
// sequence (or scoring a results folder), on a pool of threads.
#pragma once

#include <chrono>
#include <ostream>
#include <string>
#include <vector>

#include "scbt/app/eval_run.h"
#include "scbt/eval/dataset.h"
#include "scbt/eval/sequence_gap.h"
#include "scbt/geometry/polygon.h"

namespace scbt {

using EvalClock = std::chrono::steady_clock;
double seconds_since(EvalClock::time_point start);
std::string join(const std::vector<std::string>& items, const char* separator = ", ");

// A sequence's ground truth, loaded once and shared by its jobs.
struct EvalSequence {
  DatasetSequence files;
  std::vector<Polygon> truth;  // frame k at index k-1
};

// The ground truth of `sequence` (its first max_frames frames; 0: all). Throws std::runtime_error
// naming the line of a malformed or degenerate polygon.
std::vector<Polygon> load_truth(const DatasetSequence& sequence, int max_frames);

// The gap variant a run of `options` makes of a sequence with `frames` frames of ground truth.
SequenceGap sequence_gap(const EvalRunOptions& options, int frames);

// One (tracker, sequence) pair: either run a tracker or score a results folder.
struct EvalJob {
  std::string tracker;
  std::string results_dir;  // empty: run `tracker`
  const EvalSequence* sequence = nullptr;
};

struct EvalJobOutcome {
  std::vector<FrameRecord> frames;  // scored frames (a gap's frames are not scored)
  TimingStats timing;
  std::vector<std::string> warnings;
  std::string error;  // non-empty when the job failed
  double seconds = 0.0;
  // Run trackers only: every tracked frame's E_AL, confidence and state, and the gap variant.
  std::vector<LossFrame> loss;
  SequenceGap gap;
};

// Runs every job on `threads` threads, longest sequences first; logs one line per finished job
// and a heartbeat while long jobs run (unless options.quiet). A job that throws gets its error.
std::vector<EvalJobOutcome> run_eval_jobs(const std::vector<EvalJob>& jobs,
                                          const EvalRunOptions& options, int threads,
                                          std::ostream& log);

}  // namespace scbt
