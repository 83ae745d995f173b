// The polygon text format shared by ground truth, initial boundaries and results:
// one polygon per line, `n x1 y1 x2 y2 ... xn yn`, whitespace separated.
#pragma once

#include <string>
#include <vector>

#include "scbt/geometry/polygon.h"

namespace scbt {

// Parses one line. Throws std::invalid_argument with a message that names the problem (count not
// matching the coordinates, non-numeric token, non-finite value, ...). CR line ends are accepted.
Polygon parse_polygon_line(const std::string& line);

// Non-throwing variant for evaluation, where a bad line is a failed frame, not a fatal error.
bool try_parse_polygon_line(const std::string& line, Polygon* polygon, std::string* error);

// Formats a polygon as one line of the format (no trailing newline), two decimals per coordinate.
std::string format_polygon_line(const Polygon& polygon);

// Parses the inline form "x1,y1 x2,y2 ...". Throws std::invalid_argument.
Polygon parse_points_list(const std::string& text);

// All lines of a text file, CR stripped. Throws std::runtime_error naming the file if unreadable.
std::vector<std::string> read_text_lines(const std::string& path);

// The first line of a polygon file, parsed. Errors name the file and line.
Polygon read_first_polygon(const std::string& path);

// Throws std::invalid_argument unless the polygon can serve as a boundary: finite coordinates,
// at least 3 distinct vertices, non-zero area, no self-intersection.
void check_boundary_polygon(const Polygon& polygon);

}  // namespace scbt
