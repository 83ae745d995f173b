// libFuzzer target: the polygon / results text parsers and the boundary check, on arbitrary
// bytes. Any input must either parse or be refused with std::invalid_argument; a parsed polygon
// must survive a format / parse round trip with the same vertex count.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>

#include "scbt/geometry/polygon.h"
#include "scbt/geometry/polygon_io.h"

namespace {

void check_line(const std::string& line) {
  scbt::Polygon polygon;
  std::string error;
  const bool ok = scbt::try_parse_polygon_line(line, &polygon, &error);
  if (!ok && error.empty()) std::abort();  // a refusal must say why
  if (!ok) return;
  const scbt::Polygon again = scbt::parse_polygon_line(scbt::format_polygon_line(polygon));
  if (again.size() != polygon.size()) std::abort();
  try {
    scbt::check_boundary_polygon(polygon);
    (void)scbt::area(polygon);
  } catch (const std::invalid_argument&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  // A results file: every line on its own (CR stripped as read_text_lines does).
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    check_line(line);
  }
  try {
    const scbt::Polygon polygon = scbt::parse_points_list(text);
    scbt::check_boundary_polygon(polygon);
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
