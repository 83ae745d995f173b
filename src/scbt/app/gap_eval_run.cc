#include "scbt/app/gap_eval_run.h"

#include <cstdio>
#include <filesystem>

#include "scbt/io/atomic_file.h"

namespace scbt {
namespace fs = std::filesystem;
namespace {

const LossRow* find_row(const GapEvalRun& run, const std::string& tracker,
                        const std::string& sequence) {
  for (const LossRow& row : run.summary.loss) {
    if (row.tracker == tracker && row.sequence == sequence) return &row;
  }
  return nullptr;
}

std::string format(const char* pattern, double value) {
  char text[32];
  std::snprintf(text, sizeof(text), pattern, value);
  return text;
}

std::string auc_of(const LossRow* row) {
  return row && row->has_confidence && row->scores.auc ? format("%.3f", *row->scores.auc) : "-";
}

std::string delay_of(const LossRow* row) {
  if (!row) return "-";
  return row->scores.reacquire_delay >= 0 ? std::to_string(row->scores.reacquire_delay) : "never";
}

std::string after_of(const LossRow* row) {
  return row && row->scores.success_after ? format("%.3f", *row->scores.success_after) : "-";
}

double s10_of(const EvalRunSummary& s, const std::string& tracker, const std::string& sequence) {
  for (const SequenceScore& score : s.scores) {
    if (score.tracker == tracker && score.sequence == sequence) return score.errors.success_10;
  }
  return -1.0;
}

// One row per (tracker, sequence) of the clean run, the pooled row last: clean S@10 and AUC, and
// per gap variant its AUC, delay and success after re-acquisition.
void write_tables(const GapEvalSummary& summary, const std::string& out,
                  std::vector<std::string>* files) {
  AtomicFile md((fs::path(out) / "gaps_summary.md").string());
  AtomicFile csv((fs::path(out) / "gaps_summary.csv").string());
  md.stream() << "# scbt: confidence and re-acquisition on gap variants\n\n"
              << "Each sequence as it is (clean) and with a gap from its middle (or from the "
                 "fraction after @): grey30 = 30 frames replaced by uniform grey (1 s at 30 fps), "
                 "jump60 = 60 frames dropped (a 2 s jump). ROC AUC of the confidence against E_AL "
                 ">= 10 px over the scored "
                 "frames (the gap's are not scored); delay = frames from the end of the gap to the "
                 "first right frame in state `tracking`; after = S@10 from that frame on. "
                 "Pooled: AUC over all frames, the worst delay, S@10 over all frames after "
                 "re-acquisition. Details per variant in <variant>/report.md.\n\n"
              << "| tracker | sequence | clean S@10 | clean AUC |";
  csv.stream() << "tracker,sequence,clean_success_10,clean_auc";
  for (size_t v = 1; v < summary.runs.size(); ++v) {
    const std::string& name = summary.runs[v].variant;
    md.stream() << ' ' << name << " AUC | " << name << " delay | " << name << " after |";
    csv.stream() << ',' << name << "_auc," << name << "_delay," << name << "_success_after";
  }
  md.stream() << "\n|---|---|---:|---:|";
  for (size_t v = 1; v < summary.runs.size(); ++v) md.stream() << "---:|---:|---:|";
  md.stream() << '\n';
  csv.stream() << '\n';
  const GapEvalRun& clean = summary.runs.front();
  for (const LossRow& row : clean.summary.loss) {
    const double s10 = s10_of(clean.summary, row.tracker, row.sequence);
    md.stream() << "| " << row.tracker << " | " << row.sequence << " | " << format("%.3f", s10)
                << " | " << auc_of(&row) << " |";
    csv.stream() << row.tracker << ',' << row.sequence << ',' << format("%.4f", s10) << ','
                 << auc_of(&row);
    for (size_t v = 1; v < summary.runs.size(); ++v) {
      const LossRow* gap = find_row(summary.runs[v], row.tracker, row.sequence);
      md.stream() << ' ' << auc_of(gap) << " | " << delay_of(gap) << " | " << after_of(gap) << " |";
      csv.stream() << ',' << auc_of(gap) << ',' << delay_of(gap) << ',' << after_of(gap);
    }
    md.stream() << '\n';
    csv.stream() << '\n';
  }
  md.commit();
  csv.commit();
  files->push_back(md.path());
  files->push_back(csv.path());
}

}  // namespace

GapEvalSummary run_gap_evals(const EvalRunOptions& base, std::ostream& log,
                             const std::vector<double>& positions) {
  base.check();
  if (base.perturbation.frame_stride() != 1) {
    throw std::invalid_argument("--gaps cannot be combined with a frame stride");
  }
  if (positions.empty()) throw std::invalid_argument("--gap-at: no position given");
  for (double p : positions) {
    if (!(p > 0.0 && p < 1.0)) {
      throw std::invalid_argument("--gap-at: a position must be in (0, 1) of the sequence, got " +
                                  format("%g", p));
    }
  }
  // One position in the middle keeps the plain names; others are named by where they start.
  const bool named_by_position = positions.size() > 1 || positions.front() != 0.5;
  GapEvalSummary summary;
  const auto run = [&](GapVariantKind kind, double position) {
    EvalRunOptions options = base;
    options.gap = kind;
    options.gap_position = position;
    std::string variant = sequence_gap_name(kind);
    if (kind != GapVariantKind::kNone && named_by_position) variant += format("@%g", position);
    options.out = (fs::path(base.out) / variant).string();
    if (!base.quiet) log << "eval: " << variant << " -> " << options.out << '\n';
    summary.runs.push_back({variant, run_eval(options, log)});
  };
  run(GapVariantKind::kNone, 0.5);
  for (double position : positions) {
    run(GapVariantKind::kGrey, position);
    run(GapVariantKind::kDrop, position);
  }
  write_tables(summary, base.out, &summary.files);
  return summary;
}

}  // namespace scbt
