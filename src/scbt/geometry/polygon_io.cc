#include "scbt/geometry/polygon_io.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <stdexcept>

#include "scbt/io/bounded_read.h"
#include "scbt/io/printable.h"

namespace scbt {
namespace {

// Longest line we accept; a polygon of this size is far beyond any real boundary.
constexpr size_t kMaxLineLength = 1 << 20;
constexpr long kMaxVertices = 100000;

// Parses a whole token as a number. A value too small for a double (1e-310) becomes the nearest
// one (denormal or 0); one too large (1e400) is not finite and refused by the callers.
bool parse_double(const std::string& token, double* value) {
  if (token.empty()) return false;
  errno = 0;
  char* end = nullptr;
  *value = std::strtod(token.c_str(), &end);
  return end == token.c_str() + token.size();
}

bool starts_with_byte_order_mark(const std::string& text) {
  return text.size() >= 3 && text.compare(0, 3, "\xEF\xBB\xBF") == 0;
}

// True when every vertex lies on the line through the first one and the one farthest from it
// (to within a millionth of that distance).
bool all_on_one_line(const Polygon& polygon) {
  const Point& first = polygon.front();
  Point far = first;
  double far_sq = 0.0;
  for (const Point& p : polygon) {
    const double d = (p.x - first.x) * (p.x - first.x) + (p.y - first.y) * (p.y - first.y);
    if (d > far_sq) {
      far_sq = d;
      far = p;
    }
  }
  if (far_sq == 0.0) return true;
  const double length = std::sqrt(far_sq);
  for (const Point& p : polygon) {
    const double cross = (far.x - first.x) * (p.y - first.y) - (far.y - first.y) * (p.x - first.x);
    if (std::abs(cross) / length > 1e-6 * length) return false;
  }
  return true;
}

std::vector<std::string> split_whitespace(const std::string& line) {
  std::vector<std::string> tokens;
  std::istringstream stream(line);
  std::string token;
  while (stream >> token) tokens.push_back(token);
  return tokens;
}

}  // namespace

bool try_parse_polygon_line(const std::string& line, Polygon* polygon, std::string* error) {
  auto fail = [&](const std::string& message) {
    if (error) *error = message;
    return false;
  };
  if (line.size() > kMaxLineLength) return fail("line longer than 1 MiB");
  if (starts_with_byte_order_mark(line)) {
    return fail(
        "line starts with a UTF-8 byte-order mark (bytes EF BB BF); save the file without it");
  }
  const std::vector<std::string> tokens = split_whitespace(line);
  if (tokens.empty()) return fail("empty line");
  char* end = nullptr;
  errno = 0;
  const long count = std::strtol(tokens[0].c_str(), &end, 10);
  if (end != tokens[0].c_str() + tokens[0].size() || errno == ERANGE) {
    return fail("vertex count '" + printable(tokens[0]) + "' is not an integer");
  }
  if (count < 0 || count > kMaxVertices) {
    return fail("vertex count " + printable(tokens[0]) + " out of range");
  }
  const size_t expected = 1 + 2 * static_cast<size_t>(count);
  if (tokens.size() != expected) {
    return fail("vertex count " + printable(tokens[0]) + " needs " + std::to_string(2 * count) +
                " coordinates, found " + std::to_string(tokens.size() - 1));
  }
  Polygon result;
  result.reserve(count);
  for (long i = 0; i < count; ++i) {
    double x = 0, y = 0;
    const std::string& tx = tokens[1 + 2 * i];
    const std::string& ty = tokens[2 + 2 * i];
    if (!parse_double(tx, &x)) return fail("coordinate '" + printable(tx) + "' is not a number");
    if (!parse_double(ty, &y)) return fail("coordinate '" + printable(ty) + "' is not a number");
    if (!std::isfinite(x) || !std::isfinite(y)) {
      return fail("coordinate of vertex " + std::to_string(i + 1) + " ('" +
                  printable(std::isfinite(x) ? ty : tx) + "') is not finite");
    }
    result.emplace_back(x, y);
  }
  *polygon = std::move(result);
  return true;
}

Polygon parse_polygon_line(const std::string& line) {
  Polygon polygon;
  std::string error;
  if (!try_parse_polygon_line(line, &polygon, &error)) throw std::invalid_argument(error);
  return polygon;
}

std::string format_polygon_line(const Polygon& polygon) {
  std::string out = std::to_string(polygon.size());
  char buffer[64];
  for (const Point& p : polygon) {
    // Huge coordinates (up to 1e308 has 309 digits) need more than the buffer: never truncate.
    const int needed = std::snprintf(buffer, sizeof(buffer), " %.2f %.2f", p.x, p.y);
    if (needed < static_cast<int>(sizeof(buffer))) {
      out += buffer;
      continue;
    }
    std::string wide(static_cast<size_t>(needed) + 1, '\0');
    std::snprintf(wide.data(), wide.size(), " %.2f %.2f", p.x, p.y);
    wide.resize(static_cast<size_t>(needed));
    out += wide;
  }
  return out;
}

Polygon parse_points_list(const std::string& text) {
  Polygon polygon;
  for (const std::string& token : split_whitespace(text)) {
    const size_t comma = token.find(',');
    double x = 0, y = 0;
    if (comma == std::string::npos || !parse_double(token.substr(0, comma), &x) ||
        !parse_double(token.substr(comma + 1), &y)) {
      throw std::invalid_argument("point '" + printable(token) + "' is not of the form x,y");
    }
    if (!std::isfinite(x) || !std::isfinite(y)) {
      throw std::invalid_argument("point '" + printable(token) + "' is not finite");
    }
    polygon.emplace_back(x, y);
  }
  return polygon;
}

std::vector<std::string> read_text_lines(const std::string& path) {
  return read_text_lines(path, kMaxTextFileBytes, "a text file");
}

std::vector<std::string> read_text_lines(const std::string& path, std::size_t max_bytes,
                                         const std::string& what) {
  const std::string text = read_file_bounded(path, {max_bytes, what});
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
    start = end + 1;
  }
  return lines;
}

std::vector<std::string> read_polygon_lines(const std::string& path) {
  BoundedReader reader(path, {kMaxTextFileBytes, "a polygon file"});
  std::vector<std::string> lines;
  std::string line;
  while (reader.read_line(&line, kMaxLineLength)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
  }
  if (lines.empty()) throw std::runtime_error(printable(path) + ": file is empty");
  return lines;
}

Polygon read_first_polygon(const std::string& path) {
  // Up to the first newline only, never more than the line limit: the file may be huge, endless
  // (/dev/zero) or a pipe.
  BoundedReader reader(path, {kMaxTextFileBytes, "a polygon file"});
  std::string line;
  if (!reader.read_line(&line, kMaxLineLength)) {
    throw std::runtime_error(printable(path) + ": file is empty");
  }
  if (!line.empty() && line.back() == '\r') line.pop_back();
  Polygon polygon;
  std::string error;
  if (!try_parse_polygon_line(line, &polygon, &error)) {
    throw std::runtime_error(printable(path) + ":1: " + error);
  }
  return polygon;
}

int drop_repeated_vertices(Polygon* polygon) {
  Polygon kept;
  kept.reserve(polygon->size());
  for (const Point& p : *polygon) {
    if (kept.empty() || !(p == kept.back())) kept.push_back(p);
  }
  while (kept.size() > 1 && kept.back() == kept.front()) kept.pop_back();
  const int dropped = static_cast<int>(polygon->size() - kept.size());
  *polygon = std::move(kept);
  return dropped;
}

void check_boundary_polygon(const Polygon& polygon) {
  for (size_t i = 0; i < polygon.size(); ++i) {
    if (!std::isfinite(polygon[i].x) || !std::isfinite(polygon[i].y)) {
      throw std::invalid_argument("polygon vertex " + std::to_string(i + 1) + " is not finite");
    }
  }
  if (polygon.size() > static_cast<size_t>(kMaxBoundaryVertices)) {
    throw std::invalid_argument("polygon has " + std::to_string(polygon.size()) +
                                " vertices; a boundary may have at most " +
                                std::to_string(kMaxBoundaryVertices));
  }
  if (count_distinct_points(polygon) < 3) {
    throw std::invalid_argument("polygon needs at least 3 distinct vertices");
  }
  if (count_distinct_points(polygon) != static_cast<int>(polygon.size())) {
    throw std::invalid_argument("polygon repeats a vertex");
  }
  if (all_on_one_line(polygon)) {
    throw std::invalid_argument("polygon encloses no area (its vertices lie on one line)");
  }
  if (!is_simple(polygon)) throw std::invalid_argument("polygon crosses itself");
  const double enclosed = area(polygon);
  if (enclosed < kMinBoundaryArea) {
    char text[128];
    std::snprintf(text, sizeof(text), "polygon encloses %.3g px², smaller than %g px²", enclosed,
                  kMinBoundaryArea);
    throw std::invalid_argument(text);
  }
}

}  // namespace scbt
