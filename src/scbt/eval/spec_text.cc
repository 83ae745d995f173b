#include "scbt/eval/spec_text.h"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace scbt {

std::string format_spec_number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

double parse_spec_number(const std::string& text, const std::string& what, const char* grammar) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v)) {
    throw std::invalid_argument(what + ": '" + text + "' is not a number; " + grammar);
  }
  return v;
}

std::uint64_t mix_seed(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

}  // namespace scbt
