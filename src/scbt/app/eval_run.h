// The body of `scbt eval`: run trackers over a dataset laid out like the public one and/or score
// existing results files, then write the results, CSVs, Markdown report and success-curve plot.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "scbt/eval/perturb.h"
#include "scbt/eval/report.h"
#include "scbt/eval/sequence_gap.h"
#include "scbt/tracker/tracker_options.h"

namespace scbt {

struct EvalRunOptions {
  std::string dataset;                 // DIR with OriginalVideosAVI/ and GroundTruthByPolygons/
  std::vector<std::string> sequences;  // empty: all sequences of the dataset
  // Trackers to run (names of make_polygon_tracker). Empty: all of them, unless `results` is
  // given, in which case nothing is run.
  std::vector<std::string> trackers;
  // Existing results to score, "name=DIR" with DIR/<Seq>.txt (one polygon line per frame).
  std::vector<std::string> results;
  std::string out;         // output folder (created)
  int jobs = 0;            // parallel jobs; 0: std::thread::hardware_concurrency()
  int max_frames = 0;      // only the first N frames of each sequence (0: all), for quick runs
  bool quiet = false;      // no progress on the log
  bool plot = true;        // write success_curves.png
  TrackerOptions tracker;  // for "bdsp" (and peers that use them)
  // Frames are degraded like this before trackers see them (eval/perturb.h); results of a
  // downscaled run are scaled back and scored at full size, and with a frame stride only the
  // frames shown are scored. Results folders (`results`) are scored as they are.
  Perturbation perturbation;
  // A gap variant of every sequence (eval/sequence_gap.h), starting at its middle: 30 grey frames
  // or 60 dropped frames. The gap's frames are not scored. Not with a frame stride.
  GapVariantKind gap = GapVariantKind::kNone;
  double gap_position = 0.5;  // where the gap starts, as a fraction of each sequence: (0, 1)

  // Throws std::invalid_argument naming the first bad value (no file system access).
  void check() const;
};

// The confidence and loss scores of one run tracker on one sequence (or pooled: sequence
// kAllSequences): ROC AUC of the confidence against E_AL >= 10 px, and with a gap the
// re-acquisition delay and the success after it.
struct LossRow {
  std::string tracker;
  std::string sequence;
  std::string variant;          // SequenceGap::name(): clean, grey30, jump60
  bool has_confidence = false;  // false: the tracker's confidence is always 0 (it has none)
  LossScores scores;
};

struct EvalRunSummary {
  std::vector<SequenceScore> scores;  // per (tracker, sequence), then the pooled rows
  std::vector<LossRow> loss;          // per (run tracker, sequence), then the pooled rows
  std::vector<std::string> files;     // everything written, report first
  std::vector<std::string> warnings;
  double seconds = 0.0;  // wall time of the whole run
  int jobs = 0;          // (tracker, sequence) jobs
  int threads = 0;
};

// A "name=DIR" results spec split in two. Throws std::invalid_argument if malformed.
std::pair<std::string, std::string> parse_results_spec(const std::string& spec);

// Runs everything. Bad options, an unknown tracker or sequence, or a dataset not laid out as
// expected throw before any work starts. A job that fails (e.g. unreadable frame) does not stop
// the others: the report is written for the rest, then std::runtime_error names the failures.
EvalRunSummary run_eval(const EvalRunOptions& options, std::ostream& log);

}  // namespace scbt
