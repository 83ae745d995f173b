// The paper's alignment error E_AL (§IV-A) between a tracked boundary and the ground truth.
#pragma once

#include <opencv2/core/types.hpp>
#include <optional>
#include <string>
#include <vector>

#include "scbt/geometry/polygon.h"

namespace scbt {

// Each boundary is drawn as a 1-pixel-wide closed polyline on a canvas of `canvas` size; with
// Dist_B the Euclidean distance transform of boundary image B,
//   E_AL = max( mean of Dist_Bgt over B_i's pixels, mean of Dist_Bi over B_gt's pixels ),
// the perimeters being numbers of boundary pixels. Returns +infinity when either boundary is
// degenerate (see is_scorable_polygon) or draws no pixel on the canvas.
double alignment_error(const Polygon& tracked, const Polygon& truth, cv::Size canvas);

// A result polygon can be scored when it has finite coordinates, at least 3 distinct points and
// a non-zero area.
bool is_scorable_polygon(const Polygon& polygon);

// Share of `errors` strictly below `threshold` (0 for an empty list).
double success_rate(const std::vector<double>& errors, double threshold);

// E_AL of one line of a results file against the truth. A line that does not parse (count not
// matching the coordinates, non-numeric or non-finite values, empty) or whose polygon is not
// scorable is a failure: +infinity, with the reason in `note` when given (cleared otherwise).
double alignment_error_of_line(const std::string& line, const Polygon& truth, cv::Size canvas,
                               std::string* note = nullptr);

}  // namespace scbt
