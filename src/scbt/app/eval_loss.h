// The confidence and loss part of `scbt eval` (issue 18): per run tracker and sequence the ROC
// AUC of its confidence (E_AL >= 10 px positive) and, on gap variants, the re-acquisition delay
// and the success rate after it; as rows, a CSV and a section of report.md.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "scbt/app/eval_jobs.h"

namespace scbt {

// Rows in job order for the jobs that ran a tracker and succeeded, then one pooled row per
// tracker (over all its sequences, when there are several).
std::vector<LossRow> loss_rows(const std::vector<EvalJob>& jobs,
                               const std::vector<EvalJobOutcome>& outcomes,
                               const std::vector<std::string>& trackers);

// "tracker,sequence,variant,scored,wrong,auc,reacquire_delay,success_after"; nan for a value
// that is not there (no confidence, no wrong frame, never re-acquired), -1 for no delay.
void write_loss_csv(std::ostream& out, const std::vector<LossRow>& rows);

// A Markdown section for report.md: one table row per LossRow.
void write_loss_section(std::ostream& md, const std::vector<LossRow>& rows);

}  // namespace scbt
