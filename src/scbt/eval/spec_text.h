// What the perturbation and occlusion spec strings share: numbers written back as they parse, a
// number parsed with an error naming the spec and its grammar, and the seed mixing.
#pragma once

#include <cstdint>
#include <string>

namespace scbt {

// `v` as the shortest text that parses back to it ("0.3", "15").
std::string format_spec_number(double v);
// `text` as a finite number; otherwise std::invalid_argument "WHAT: 'TEXT' is not a number;
// GRAMMAR" (WHAT names the spec, e.g. "perturbation 'noise:x'").
double parse_spec_number(const std::string& text, const std::string& what, const char* grammar);
// SplitMix64: a well-mixed 64-bit hash, for seeds that must differ per frame or per use.
std::uint64_t mix_seed(std::uint64_t x);

}  // namespace scbt
