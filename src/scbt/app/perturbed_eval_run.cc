#include "scbt/app/perturbed_eval_run.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <opencv2/imgproc.hpp>

#include "scbt/eval/plot.h"
#include "scbt/io/atomic_file.h"
#include "scbt/io/printable.h"

namespace scbt {
namespace fs = std::filesystem;
namespace {

std::string kind_of(const Perturbation& p) { return p.name().substr(0, p.name().find(':')); }

const SequenceScore* find_score(const EvalRunSummary& s, const std::string& tracker,
                                const std::string& sequence) {
  for (const SequenceScore& score : s.scores) {
    if (score.tracker == tracker && score.sequence == sequence) return &score;
  }
  return nullptr;
}

// The trackers and sequences of a run, in report order (pooled row excluded).
void names_of(const EvalRunSummary& s, std::vector<std::string>* trackers,
              std::vector<std::string>* sequences) {
  for (const SequenceScore& score : s.scores) {
    if (std::find(trackers->begin(), trackers->end(), score.tracker) == trackers->end()) {
      trackers->push_back(score.tracker);
    }
    if (score.sequence != kAllSequences &&
        std::find(sequences->begin(), sequences->end(), score.sequence) == sequences->end()) {
      sequences->push_back(score.sequence);
    }
  }
}

void write_tables(const PerturbedEvalSummary& summary, const std::string& out,
                  std::vector<std::string>* files) {
  std::vector<std::string> trackers, sequences;
  for (const PerturbedEvalRun& run : summary.runs) names_of(run.summary, &trackers, &sequences);
  AtomicFile md((fs::path(out) / "perturb_summary.md").string());
  AtomicFile csv((fs::path(out) / "perturb_summary.csv").string());
  md.stream() << "# scbt evaluation under perturbations\n\n"
              << "Success rate = share of frames with E_AL below 5 / 10 / 20 px; per-sequence "
                 "columns are success at 10 px. Each perturbation's full report is in its "
                 "folder.\n\n| perturbation | tracker | S@5 | S@10 | S@20 | AUC | held |";
  csv.stream() << "perturbation,tracker,sequence,frames,success_5,success_10,success_20,auc,held\n";
  for (const std::string& s : sequences) md.stream() << ' ' << s << " |";
  md.stream() << "\n|---|---|---|---|---|---|---|";
  for (size_t i = 0; i < sequences.size(); ++i) md.stream() << "---|";
  md.stream() << '\n';
  char cell[64];
  for (const PerturbedEvalRun& run : summary.runs) {
    const std::string name = run.perturbation.name();
    for (const std::string& tracker : trackers) {
      std::vector<std::string> rows = sequences;
      rows.push_back(kAllSequences);
      for (const std::string& seq : rows) {
        const SequenceScore* s = find_score(run.summary, tracker, seq);
        if (s == nullptr) continue;
        csv.stream() << csv_field(name) << ',' << tracker << ',' << seq << ',' << s->errors.frames
                     << ',' << s->errors.success_5 << ',' << s->errors.success_10 << ','
                     << s->errors.success_20 << ',' << s->errors.auc << ','
                     << (s->timing.has_timing ? std::to_string(s->timing.held) : "") << '\n';
      }
      const SequenceScore* pooled = find_score(run.summary, tracker, kAllSequences);
      if (pooled == nullptr && sequences.size() == 1) {
        pooled = find_score(run.summary, tracker, sequences.front());
      }
      if (pooled == nullptr) continue;
      std::snprintf(cell, sizeof(cell), "| %.3f | %.3f | %.3f | %.3f | %s |",
                    pooled->errors.success_5, pooled->errors.success_10, pooled->errors.success_20,
                    pooled->errors.auc,
                    pooled->timing.has_timing ? std::to_string(pooled->timing.held).c_str() : "");
      md.stream() << "| `" << name << "` | " << tracker << ' ' << cell;
      for (const std::string& seq : sequences) {
        const SequenceScore* s = find_score(run.summary, tracker, seq);
        if (s == nullptr) {
          md.stream() << " |";
        } else {
          std::snprintf(cell, sizeof(cell), " %.3f |", s->errors.success_10);
          md.stream() << cell;
        }
      }
      md.stream() << '\n';
    }
  }
  md.commit();
  csv.commit();
  files->push_back(md.path());
  files->push_back(csv.path());
}

// Pooled success at 10 px of `tracker` in `run` (a single sequence's when there is no pooled
// row), or -1 when the run has none.
double pooled_s10(const PerturbedEvalRun& run, const std::string& tracker,
                  const std::vector<std::string>& sequences) {
  const SequenceScore* s = find_score(run.summary, tracker, kAllSequences);
  if (s == nullptr && sequences.size() == 1) s = find_score(run.summary, tracker, sequences[0]);
  return s == nullptr ? -1.0 : s->errors.success_10;
}

// Where a (level, success) pair falls in a plot spanning levels lo..hi and success 0..1.
struct LevelAxes {
  cv::Rect plot;
  double lo, hi;
  cv::Point to_px(double level, double s) const {
    return cv::Point(plot.x + static_cast<int>((level - lo) / (hi - lo) * plot.width),
                     plot.y + static_cast<int>((1.0 - s) * plot.height));
  }
};

// The frame, grid, titles and level labels of one kind's panel.
void draw_level_axes(const LevelAxes& axes, const cv::Rect& panel, const std::string& kind,
                     const std::vector<const PerturbedEvalRun*>& runs, cv::Mat* image) {
  const cv::Scalar ink(40, 40, 40), grid(220, 220, 220);
  const cv::Rect& plot = axes.plot;
  for (int i = 0; i <= 4; ++i) {
    const int y = plot.y + plot.height * i / 4;
    cv::line(*image, {plot.x, y}, {plot.x + plot.width, y}, grid, 1);
    char label[16];
    std::snprintf(label, sizeof(label), "%.2f", 1.0 - 0.25 * i);
    cv::putText(*image, label, {panel.x + 8, y + 4}, cv::FONT_HERSHEY_SIMPLEX, 0.4, ink, 1,
                cv::LINE_AA);
  }
  cv::rectangle(*image, plot, ink, 1);
  cv::putText(*image, kind + " level", {plot.x + plot.width / 2 - 40, panel.y + panel.height - 12},
              cv::FONT_HERSHEY_SIMPLEX, 0.45, ink, 1, cv::LINE_AA);
  cv::putText(*image, "pooled success@10 under " + kind, {panel.x + 10, panel.y + 18},
              cv::FONT_HERSHEY_SIMPLEX, 0.45, ink, 1, cv::LINE_AA);
  for (const PerturbedEvalRun* run : runs) {
    char label[32];
    std::snprintf(label, sizeof(label), "%g", run->perturbation.level);
    const cv::Point at = axes.to_px(run->perturbation.level, 0.0);
    cv::putText(*image, label, {at.x - 8, at.y + 16}, cv::FONT_HERSHEY_SIMPLEX, 0.4, ink, 1,
                cv::LINE_AA);
  }
}

// One kind's panel: a polyline and dots per tracker over the levels, the unperturbed run (when
// given) as a dashed level.
void draw_level_panel(const PerturbedEvalSummary& summary, const std::string& kind,
                      const std::vector<std::string>& trackers,
                      const std::vector<std::string>& sequences, const cv::Rect& panel,
                      cv::Mat* image) {
  std::vector<const PerturbedEvalRun*> runs;
  LevelAxes axes{cv::Rect(panel.x + 50, panel.y + 30, panel.width - 70, panel.height - 75), 1e300,
                 -1e300};
  for (const PerturbedEvalRun& run : summary.runs) {
    if (kind_of(run.perturbation) != kind) continue;
    runs.push_back(&run);
    axes.lo = std::min(axes.lo, run.perturbation.level);
    axes.hi = std::max(axes.hi, run.perturbation.level);
  }
  std::sort(runs.begin(), runs.end(), [](const PerturbedEvalRun* a, const PerturbedEvalRun* b) {
    return a->perturbation.level < b->perturbation.level;
  });
  if (!(axes.hi > axes.lo)) {
    axes.lo -= 1;
    axes.hi += 1;
  }
  draw_level_axes(axes, panel, kind, runs, image);
  const cv::Rect& plot = axes.plot;
  for (size_t t = 0; t < trackers.size(); ++t) {
    const cv::Scalar colour = plot_colour(t);
    for (const PerturbedEvalRun& run : summary.runs) {
      const double s =
          kind_of(run.perturbation) == "none" ? pooled_s10(run, trackers[t], sequences) : -1.0;
      if (s < 0) continue;
      const int y = axes.to_px(axes.lo, s).y;
      for (int x = plot.x; x < plot.x + plot.width; x += 12) {
        cv::line(*image, {x, y}, {std::min(x + 6, plot.x + plot.width), y}, colour, 1);
      }
    }
    cv::Point previous(-1, -1);
    for (const PerturbedEvalRun* run : runs) {
      const double s = pooled_s10(*run, trackers[t], sequences);
      if (s < 0) continue;
      const cv::Point p = axes.to_px(run->perturbation.level, s);
      if (previous.x >= 0) cv::line(*image, previous, p, colour, 2, cv::LINE_AA);
      cv::circle(*image, p, 4, colour, cv::FILLED, cv::LINE_AA);
      previous = p;
    }
    cv::putText(*image, trackers[t],
                {plot.x + 8, plot.y + plot.height - 10 - 16 * static_cast<int>(t)},
                cv::FONT_HERSHEY_SIMPLEX, 0.45, colour, 1, cv::LINE_AA);
  }
}

// One panel per kind of perturbation: pooled success at 10 px (y, 0..1) against its level (x).
cv::Mat render_levels(const PerturbedEvalSummary& summary) {
  std::vector<std::string> kinds, trackers, sequences;
  for (const PerturbedEvalRun& run : summary.runs) {
    names_of(run.summary, &trackers, &sequences);
    const std::string kind = kind_of(run.perturbation);
    if (kind != "none" && std::find(kinds.begin(), kinds.end(), kind) == kinds.end()) {
      kinds.push_back(kind);
    }
  }
  if (kinds.empty()) kinds.push_back("none");
  const int pw = 360, ph = 280, columns = std::min<int>(4, static_cast<int>(kinds.size()));
  const int rows = (static_cast<int>(kinds.size()) + columns - 1) / columns;
  cv::Mat image(rows * ph, columns * pw, CV_8UC3, cv::Scalar(255, 255, 255));
  for (size_t k = 0; k < kinds.size(); ++k) {
    const cv::Rect panel((k % columns) * pw, (k / columns) * ph, pw, ph);
    draw_level_panel(summary, kinds[k], trackers, sequences, panel, &image);
  }
  return image;
}

}  // namespace

std::string perturbation_folder(const Perturbation& perturbation) {
  std::string name = perturbation.name();
  std::replace(name.begin(), name.end(), ':', '_');
  std::replace(name.begin(), name.end(), ',', '_');
  return name;
}

PerturbedEvalSummary run_perturbed_evals(const EvalRunOptions& base,
                                         const std::vector<Perturbation>& perturbations,
                                         std::ostream& log) {
  if (perturbations.empty()) throw std::invalid_argument("--perturb: no perturbation given");
  base.check();
  std::map<std::string, int> seen;
  for (const Perturbation& p : perturbations) {
    p.check();
    if (seen[p.name()]++ > 0) {
      throw std::invalid_argument("--perturb: " + p.name() + " given twice");
    }
  }
  PerturbedEvalSummary summary;
  for (const Perturbation& p : perturbations) {
    EvalRunOptions options = base;
    options.perturbation = p;
    const std::string folder = perturbation_folder(p);
    options.out = (fs::path(base.out) / folder).string();
    if (!base.quiet) log << "eval: perturbation " << p.name() << " -> " << options.out << '\n';
    summary.runs.push_back({p, folder, run_eval(options, log)});
  }
  write_tables(summary, base.out, &summary.files);
  if (base.plot) {
    const std::string png = (fs::path(base.out) / "perturb_levels.png").string();
    write_png(png, render_levels(summary));
    summary.files.push_back(png);
  }
  return summary;
}

}  // namespace scbt
