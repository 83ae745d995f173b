// Evaluation outputs: the summary CSV (written and read back, so reports can be rebuilt and
// compared), the per-frame CSV, the success-curve CSV and the Markdown report.
#pragma once

#include <istream>
#include <ostream>
#include <string>
#include <vector>

#include "scbt/eval/success_curve.h"

namespace scbt {

// The paper's Table I columns for one tracked sequence, averaged over the tracked frames
// (the initial frame excluded). Absent (has_timing false) for scored results files.
struct TimingStats {
  bool has_timing = false;
  int tracked = 0;           // frames passed to track()
  int held = 0;              // of which the tracker kept its previous boundary
  double edges = 0.0;        // mean graph edges
  double nodes = 0.0;        // mean graph vertices
  double line_ms = 0.0;      // mean line detection time (lt)
  double grouping_ms = 0.0;  // mean grouping time (gt)
  double track_ms = 0.0;     // mean wall time of one track() call
  double fps = 0.0;          // mean over frames of the instantaneous 1000 / track_ms (paper)
};

// One row of the summary: a tracker on a sequence (or kAllSequences: every frame pooled).
struct SequenceScore {
  std::string tracker;
  std::string sequence;
  ErrorStats errors;
  TimingStats timing;
};

inline constexpr const char* kAllSequences = "(all)";

// Header + one line per score. Non-finite values are written as inf / nan, absent timing as
// empty fields. Tracker and sequence names must not contain ',', '"' or line breaks
// (std::invalid_argument otherwise).
void write_summary_csv(std::ostream& out, const std::vector<SequenceScore>& scores);

// Reads what write_summary_csv wrote (columns found by header name, so added columns are
// tolerated). Throws std::runtime_error naming the line of a malformed row.
std::vector<SequenceScore> read_summary_csv(std::istream& in);

// One scored frame, for the per-frame CSV.
struct FrameRecord {
  int frame = 0;      // 1-based
  double e_al = 0.0;  // +infinity for a failure
  std::string note;   // why a frame failed ("missing line", parse error, ...), else empty
  bool has_timing = false;
  bool held = false;
  int nodes = 0;
  int edges = 0;
  double line_ms = 0.0;
  double grouping_ms = 0.0;
  double track_ms = 0.0;
};

void write_frame_csv_header(std::ostream& out);
void write_frame_csv_rows(std::ostream& out, const std::string& tracker,
                          const std::string& sequence, const std::vector<FrameRecord>& frames);

// tracker,sequence,threshold,success_rate: the plotted curves, for other plotting tools.
struct NamedCurve {
  std::string tracker;
  std::string sequence;
  SuccessCurve curve;
};
void write_curves_csv(std::ostream& out, const std::vector<NamedCurve>& curves);

struct ReportInfo {
  std::string title = "scbt evaluation";
  std::string dataset;             // dataset folder
  std::vector<std::string> notes;  // extra lines (command, options, timing, warnings)
  std::string plot_file;           // relative path of the success-curve PNG, if any
};

// The Markdown report: success at 5/10/20 px, mean and median E_AL, AUC and failures per
// sequence and tracker, the pooled rows, and the Table I columns for trackers with timing.
void write_markdown_report(std::ostream& out, const std::vector<SequenceScore>& scores,
                           const ReportInfo& info);

}  // namespace scbt
