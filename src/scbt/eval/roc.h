// Area under the ROC curve of a score that should rank positives above negatives (here: how well
// a low confidence picks out the frames whose E_AL is at least 10 px).
#pragma once

#include <optional>
#include <vector>

namespace scbt {

// The probability that a random positive scores above a random negative, ties counting half
// (the Mann-Whitney U statistic over both counts). std::nullopt without a positive or a negative.
// Throws std::invalid_argument when the sizes differ.
std::optional<double> roc_auc(const std::vector<double>& scores, const std::vector<bool>& positive);

}  // namespace scbt
