#include "scbt/app/eval_loss.h"

#include <algorithm>
#include <cstdio>

#include "scbt/eval/roc.h"

namespace scbt {
namespace {

constexpr double kWrongPx = 10.0;  // E_AL of a wrong frame, as the issue defines it

// Pools a tracker's sequences: the AUC over all their scored frames together, the worst delay
// (-1 when one was never re-acquired), the success over all frames after re-acquisition.
LossRow pooled_row(const std::string& tracker, const std::vector<EvalJob>& jobs,
                   const std::vector<EvalJobOutcome>& outcomes) {
  LossRow row{tracker, kAllSequences, "", false, {}};
  std::vector<double> doubt;
  std::vector<bool> wrong;
  double after_right = 0.0;
  bool all_reacquired = true;
  for (size_t i = 0; i < jobs.size(); ++i) {
    const EvalJobOutcome& o = outcomes[i];
    if (jobs[i].tracker != tracker || !jobs[i].results_dir.empty() || !o.error.empty()) continue;
    row.variant = o.gap.name();
    for (const LossFrame& f : o.loss) {
      if (o.gap.in_gap(f.index)) continue;
      doubt.push_back(1.0 - f.confidence);
      wrong.push_back(!(f.e_al < kWrongPx));
      row.has_confidence = row.has_confidence || f.confidence > 0.0;
    }
    const LossScores s = score_loss(o.loss, o.gap, kWrongPx);
    row.scores.scored += s.scored;
    row.scores.wrong += s.wrong;
    row.scores.after += s.after;
    after_right += s.success_after.value_or(0.0) * s.after;
    all_reacquired = all_reacquired && s.reacquire_delay >= 0;
    row.scores.reacquire_delay = std::max(row.scores.reacquire_delay, s.reacquire_delay);
  }
  row.scores.auc = roc_auc(doubt, wrong);
  if (!all_reacquired) row.scores.reacquire_delay = -1;
  if (row.scores.after > 0) row.scores.success_after = after_right / row.scores.after;
  return row;
}

std::string number(const std::optional<double>& value, const char* format, const char* none) {
  if (!value) return none;
  char text[32];
  std::snprintf(text, sizeof(text), format, *value);
  return text;
}

}  // namespace

std::vector<LossRow> loss_rows(const std::vector<EvalJob>& jobs,
                               const std::vector<EvalJobOutcome>& outcomes,
                               const std::vector<std::string>& trackers) {
  std::vector<LossRow> rows;
  for (const std::string& tracker : trackers) {
    int sequences = 0;
    for (size_t i = 0; i < jobs.size(); ++i) {
      const EvalJobOutcome& o = outcomes[i];
      if (jobs[i].tracker != tracker || !jobs[i].results_dir.empty() || !o.error.empty()) continue;
      LossRow row{tracker, jobs[i].sequence->files.name, o.gap.name(), false,
                  score_loss(o.loss, o.gap, kWrongPx)};
      for (const LossFrame& f : o.loss) row.has_confidence = row.has_confidence || f.confidence > 0;
      rows.push_back(row);
      ++sequences;
    }
    if (sequences > 1) rows.push_back(pooled_row(tracker, jobs, outcomes));
  }
  return rows;
}

void write_loss_csv(std::ostream& out, const std::vector<LossRow>& rows) {
  out << "tracker,sequence,variant,scored,wrong,auc,reacquire_delay,success_after\n";
  for (const LossRow& r : rows) {
    const std::optional<double> auc = r.has_confidence ? r.scores.auc : std::nullopt;
    out << r.tracker << ',' << r.sequence << ',' << r.variant << ',' << r.scores.scored << ','
        << r.scores.wrong << ',' << number(auc, "%.4f", "nan") << ',' << r.scores.reacquire_delay
        << ',' << number(r.scores.success_after, "%.4f", "nan") << '\n';
  }
}

void write_loss_section(std::ostream& md, const std::vector<LossRow>& rows) {
  if (rows.empty()) return;
  const bool gaps = rows.front().variant != "clean";
  md << "\n## Confidence and loss\n\n"
     << "ROC AUC: how well a low confidence picks out the frames with E_AL >= 10 px (1: "
        "perfectly, 0.5: no better than chance; `-` without a wrong frame, or for a tracker "
        "reporting no confidence).";
  if (gaps) {
    md << " Variant " << rows.front().variant
       << ": the gap's frames are not scored; re-acquisition delay = frames from the end of the "
          "gap to the first right frame in state `tracking` (`never`: not within the sequence); "
          "S@10 after = success at 10 px from that frame on. The pooled row gives the worst "
          "delay.";
  }
  md << "\n\n| tracker | sequence | scored | E_AL>=10 | ROC AUC |"
     << (gaps ? " re-acq. delay | S@10 after |" : "") << "\n|---|---|---:|---:|---:|"
     << (gaps ? "---:|---:|" : "") << '\n';
  for (const LossRow& r : rows) {
    const std::optional<double> auc = r.has_confidence ? r.scores.auc : std::nullopt;
    md << "| " << r.tracker << " | " << r.sequence << " | " << r.scores.scored << " | "
       << r.scores.wrong << " | " << number(auc, "%.3f", "-") << " |";
    if (gaps) {
      md << ' '
         << (r.scores.reacquire_delay >= 0 ? std::to_string(r.scores.reacquire_delay) : "never")
         << " | " << number(r.scores.success_after, "%.3f", "-") << " |";
    }
    md << '\n';
  }
}

}  // namespace scbt
