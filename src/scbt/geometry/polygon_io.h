// The polygon text format shared by ground truth, initial boundaries and results:
// one polygon per line, `n x1 y1 x2 y2 ... xn yn`, whitespace separated.
#pragma once

#include <cstddef>
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

// All lines of a text file, CR stripped. Throws std::runtime_error naming the file if unreadable
// or larger than 256 MiB (checked while reading: the file may be endless, like /dev/zero).
std::vector<std::string> read_text_lines(const std::string& path);
// The same with another limit, named in the error with `what` ("a results file").
std::vector<std::string> read_text_lines(const std::string& path, std::size_t max_bytes,
                                         const std::string& what);

// All lines of a polygon file, CR stripped, unparsed; each at most 1 MiB long (the longest line
// the format allows), the file at most 256 MiB. Errors name the file (and line).
std::vector<std::string> read_polygon_lines(const std::string& path);

// The first line of a polygon file, parsed; the file is read only up to its first newline, and
// at most 1 MiB of it. Errors name the file and line.
Polygon read_first_polygon(const std::string& path);

// The most vertices a boundary may have. Its validation (is_simple) sweeps the edges, O(n log n)
// for typical outlines, but n^2 / 2 edge pairs for a zigzag whose edges all overlap in x: at this
// limit that worst case takes 0.25 s of CPU, a circle 5 ms (build/bench/scbt_polygon_check_bench,
// BM_CheckComb/20000 and BM_CheckCircle/20000; all pairs took 12 s for 60,000 vertices).
constexpr int kMaxBoundaryVertices = 20000;

// Drops each vertex equal to the one before it, and last ones equal to the first (ground-truth
// files repeat vertices so); returns how many were dropped. A vertex repeated elsewhere stays,
// and check_boundary_polygon refuses it.
int drop_repeated_vertices(Polygon* polygon);

// The least area a boundary may enclose (px²).
constexpr double kMinBoundaryArea = 1.0;

// Throws std::invalid_argument unless the polygon can serve as a boundary: finite coordinates,
// at most kMaxBoundaryVertices, at least 3 distinct vertices, no repeated vertex, not all on one
// line, no self-intersection ("crosses itself"), at least kMinBoundaryArea enclosed.
void check_boundary_polygon(const Polygon& polygon);

}  // namespace scbt
