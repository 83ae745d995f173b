#include "scbt/geometry/polygon_io.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

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
    return fail("vertex count '" + tokens[0] + "' is not an integer");
  }
  if (count < 0 || count > kMaxVertices) {
    return fail("vertex count " + tokens[0] + " out of range");
  }
  const size_t expected = 1 + 2 * static_cast<size_t>(count);
  if (tokens.size() != expected) {
    return fail("vertex count " + tokens[0] + " needs " + std::to_string(2 * count) +
                " coordinates, found " + std::to_string(tokens.size() - 1));
  }
  Polygon result;
  result.reserve(count);
  for (long i = 0; i < count; ++i) {
    double x = 0, y = 0;
    const std::string& tx = tokens[1 + 2 * i];
    const std::string& ty = tokens[2 + 2 * i];
    if (!parse_double(tx, &x)) return fail("coordinate '" + tx + "' is not a number");
    if (!parse_double(ty, &y)) return fail("coordinate '" + ty + "' is not a number");
    if (!std::isfinite(x) || !std::isfinite(y)) {
      return fail("coordinate of vertex " + std::to_string(i + 1) + " ('" +
                  (std::isfinite(x) ? ty : tx) + "') is not finite");
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
      throw std::invalid_argument("point '" + token + "' is not of the form x,y");
    }
    if (!std::isfinite(x) || !std::isfinite(y)) {
      throw std::invalid_argument("point '" + token + "' is not finite");
    }
    polygon.emplace_back(x, y);
  }
  return polygon;
}

std::vector<std::string> read_text_lines(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw std::runtime_error(path + ": cannot open for reading");
  std::vector<std::string> lines;
  std::string line;
  while (std::getline(file, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
  }
  if (file.bad()) throw std::runtime_error(path + ": read error");
  return lines;
}

Polygon read_first_polygon(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error(path + ": cannot open for reading");
  // Read up to the first newline only, never more than the line limit: the file may be huge,
  // endless (/dev/zero) or a pipe.
  std::string line;
  char chunk[4096];
  bool found_newline = false;
  while (!found_newline && line.size() <= kMaxLineLength) {
    file.read(chunk, sizeof(chunk));
    const std::streamsize got = file.gcount();
    if (got <= 0) break;
    const char* newline = static_cast<const char*>(std::memchr(chunk, '\n', got));
    found_newline = newline != nullptr;
    line.append(chunk, found_newline ? newline - chunk : got);
  }
  if (file.bad()) throw std::runtime_error(path + ": read error");
  if (line.size() > kMaxLineLength) {
    throw std::runtime_error(path + ":1: line longer than 1 MiB (the limit of the polygon format)");
  }
  if (line.empty() && !found_newline) throw std::runtime_error(path + ": file is empty");
  if (!line.empty() && line.back() == '\r') line.pop_back();
  Polygon polygon;
  std::string error;
  if (!try_parse_polygon_line(line, &polygon, &error)) {
    throw std::runtime_error(path + ":1: " + error);
  }
  return polygon;
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
  if (area(polygon) < 1.0) throw std::invalid_argument("polygon encloses no area");
  if (!is_simple(polygon)) throw std::invalid_argument("polygon intersects itself");
}

}  // namespace scbt
