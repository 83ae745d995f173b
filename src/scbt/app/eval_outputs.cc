#include "scbt/app/eval_outputs.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>

#include "scbt/app/eval_loss.h"
#include "scbt/eval/plot.h"
#include "scbt/io/atomic_file.h"
#include "scbt/tracker/option_table.h"

namespace scbt {
namespace fs = std::filesystem;
namespace {

// Means of the per-sequence timings weighted by their tracked frames.
TimingStats pool_timing(const std::vector<const TimingStats*>& parts) {
  TimingStats pooled;
  double fps_weight = 0.0;
  for (const TimingStats* t : parts) {
    if (!t->has_timing) return TimingStats{};
    pooled.has_timing = true;
    pooled.tracked += t->tracked;
    pooled.held += t->held;
    pooled.edges += t->edges * t->tracked;
    pooled.nodes += t->nodes * t->tracked;
    pooled.line_ms += t->line_ms * t->tracked;
    pooled.grouping_ms += t->grouping_ms * t->tracked;
    pooled.track_ms += t->track_ms * t->tracked;
    if (std::isfinite(t->fps)) {
      pooled.fps += t->fps * t->tracked;
      fps_weight += t->tracked;
    }
  }
  if (pooled.tracked > 0) {
    const double n = pooled.tracked;
    pooled.edges /= n;
    pooled.nodes /= n;
    pooled.line_ms /= n;
    pooled.grouping_ms /= n;
    pooled.track_ms /= n;
  }
  pooled.fps = fps_weight > 0 ? pooled.fps / fps_weight : std::numeric_limits<double>::quiet_NaN();
  return pooled;
}

// Scores and curves in a stable order: trackers as given, then results; sequences as selected.
struct Scored {
  std::vector<std::string> failures;
  std::vector<NamedCurve> curves;
  std::map<std::string, PlotPanel> panels;
  PlotPanel all_panel{"All sequences", {}};
};

void add_tracker_scores(const std::string& name, const EvalRunContext& run, EvalRunSummary* summary,
                        Scored* scored) {
  std::vector<double> pooled_errors;
  std::vector<const TimingStats*> timings;
  bool complete = true;
  for (size_t i = 0; i < run.jobs.size(); ++i) {
    if (run.jobs[i].tracker != name) continue;
    const EvalJobOutcome& o = run.outcomes[i];
    const std::string& seq = run.jobs[i].sequence->files.name;
    for (const std::string& w : o.warnings) summary->warnings.push_back(w);
    if (!o.error.empty()) {
      scored->failures.push_back(name + "/" + seq + ": " + o.error);
      complete = false;
      continue;
    }
    std::vector<double> errors;
    for (const FrameRecord& f : o.frames) errors.push_back(f.e_al);
    pooled_errors.insert(pooled_errors.end(), errors.begin(), errors.end());
    timings.push_back(&o.timing);
    SequenceScore score{name, seq, error_stats(errors), o.timing};
    summary->scores.push_back(score);
    const SuccessCurve curve = success_curve(errors);
    scored->curves.push_back({name, seq, curve});
    PlotPanel& panel = scored->panels[seq];
    panel.title = seq;
    panel.lines.push_back({name, curve, score.errors.auc});
  }
  if (run.sequences.size() > 1 && complete && !pooled_errors.empty()) {
    SequenceScore pooled{name, kAllSequences, error_stats(pooled_errors), pool_timing(timings)};
    summary->scores.push_back(pooled);
    const SuccessCurve curve = success_curve(pooled_errors);
    scored->curves.push_back({name, kAllSequences, curve});
    scored->all_panel.lines.push_back({name, curve, pooled.errors.auc});
  }
}

template <typename Write>
void write_file(const fs::path& path, EvalRunSummary* summary, Write write) {
  AtomicFile file(path.string());
  write(file.stream());
  file.commit();
  summary->files.push_back(file.path());
}

void add_notes(const EvalRunOptions& options, const EvalRunContext& run,
               const EvalRunSummary& summary, const std::vector<std::string>& failures,
               ReportInfo* info) {
  if (!run.trackers.empty()) {
    info->notes.push_back("Trackers run: " + join(run.trackers) +
                          " (initialised from ground-truth "
                          "line 1; results in <tracker>/<Seq>.txt)");
    info->notes.push_back("scbt options: " + tracker_options_repr(options.tracker));
    if (options.perturbation.kind != PerturbationKind::kNone) {
      info->notes.push_back("Frames perturbed: " + options.perturbation.name() +
                            " (eval/perturb.h; seed " + std::to_string(options.perturbation.seed) +
                            ")");
    }
    if (options.gap != GapVariantKind::kNone) {
      info->notes.push_back(
          "Gap variant: " + sequence_gap_name(options.gap) +
          " from the middle of each sequence (eval/sequence_gap.h); its frames are not scored");
    }
  }
  for (const auto& [name, dir] : run.results) {
    info->notes.push_back("Results scored: " + name + " = `" + dir + "`");
  }
  std::vector<std::string> sequence_names;
  for (const EvalSequence& s : run.sequences) sequence_names.push_back(s.files.name);
  info->notes.push_back("Sequences: " + join(sequence_names) +
                        (options.max_frames > 0
                             ? " (first " + std::to_string(options.max_frames) + " frames only)"
                             : ""));
  char timing[200];
  std::snprintf(timing, sizeof(timing),
                "%d jobs on %d threads in %.1f s wall time (timings are per process and grow "
                "when jobs share cores)",
                summary.jobs, run.threads, summary.seconds);
  info->notes.push_back(timing);
  for (const std::string& w : summary.warnings) info->notes.push_back("Warning: " + w);
  for (const std::string& f : failures) info->notes.push_back("FAILED: " + f);
}

}  // namespace

std::vector<std::string> write_eval_outputs(const EvalRunOptions& options,
                                            const EvalRunContext& run, EvalRunSummary* summary,
                                            EvalClock::time_point start) {
  Scored scored;
  std::vector<std::string> names = run.trackers;
  for (const auto& r : run.results) names.push_back(r.first);
  for (const std::string& name : names) add_tracker_scores(name, run, summary, &scored);
  summary->loss = loss_rows(run.jobs, run.outcomes, run.trackers);

  const fs::path out(options.out);
  write_file(out / "frames.csv", summary, [&](std::ostream& s) {
    write_frame_csv_header(s);
    for (size_t i = 0; i < run.jobs.size(); ++i) {
      if (run.outcomes[i].error.empty()) {
        write_frame_csv_rows(s, run.jobs[i].tracker, run.jobs[i].sequence->files.name,
                             run.outcomes[i].frames);
      }
    }
  });
  write_file(out / "summary.csv", summary,
             [&](std::ostream& s) { write_summary_csv(s, summary->scores); });
  write_file(out / "curves.csv", summary,
             [&](std::ostream& s) { write_curves_csv(s, scored.curves); });
  if (!summary->loss.empty()) {
    write_file(out / "loss.csv", summary,
               [&](std::ostream& s) { write_loss_csv(s, summary->loss); });
  }
  ReportInfo info;
  info.dataset = options.dataset;
  if (options.plot) {
    std::vector<PlotPanel> shown;
    for (const EvalSequence& s : run.sequences) {
      if (scored.panels.count(s.files.name)) shown.push_back(scored.panels[s.files.name]);
    }
    if (!scored.all_panel.lines.empty()) shown.push_back(scored.all_panel);
    const std::string png = (out / "success_curves.png").string();
    write_png(png, render_success_curves(shown));
    summary->files.push_back(png);
    info.plot_file = "success_curves.png";
  }
  summary->seconds = seconds_since(start);
  add_notes(options, run, *summary, scored.failures, &info);
  AtomicFile file((out / "report.md").string());
  write_markdown_report(file.stream(), summary->scores, info);
  write_loss_section(file.stream(), summary->loss);
  file.commit();
  summary->files.insert(summary->files.begin(), file.path());
  return scored.failures;
}

}  // namespace scbt
