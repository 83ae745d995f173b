#include "scbt/tracker/option_table.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <opencv2/core.hpp>
#include <sstream>
#include <type_traits>

namespace scbt {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

const char* const kDetection = "Line detection";
const char* const kGrouping = "Grouping";
const char* const kChoice = "Boundary choice";
const char* const kCamera = "Camera robustness";
const char* const kLoss = "Loss handling";

// A table row for a member reached through `field` (a function returning a reference into the
// options, so that nested structs' fields are rows too).
template <typename T, typename Field>
OptionSpec row(const char* name, OptionType type, const char* group, const char* help,
               Field field) {
  OptionSpec spec;
  spec.name = name;
  spec.type = type;
  spec.group = group;
  spec.help = help;
  spec.get = [field](const TrackerOptions& o) -> OptionValue {
    const T value = field(const_cast<TrackerOptions&>(o));
    if constexpr (std::is_same_v<T, bool>) {
      return value;
    } else if constexpr (std::is_same_v<T, int>) {
      return static_cast<long long>(value);
    } else {
      return static_cast<double>(value);
    }
  };
  spec.set = [field](TrackerOptions* o, const OptionValue& value) {
    if constexpr (std::is_same_v<T, bool>) {
      field(*o) = std::get<bool>(value);
    } else if constexpr (std::is_same_v<T, int>) {
      field(*o) = static_cast<int>(std::get<long long>(value));
    } else {
      field(*o) = std::get<double>(value);
    }
  };
  return spec;
}

template <typename Field>
OptionSpec bool_row(const char* name, const char* group, const char* help, Field field) {
  return row<bool>(name, OptionType::kBool, group, help, field);
}

template <typename Field>
OptionSpec int_row(const char* name, const char* group, const char* help, int min, int max,
                   Field field) {
  OptionSpec spec = row<int>(name, OptionType::kInt, group, help, field);
  spec.min = min;
  spec.max = max;
  return spec;
}

template <typename Field>
OptionSpec double_row(const char* name, const char* group, const char* help, double min,
                      bool min_open, double max, bool max_open, Field field) {
  OptionSpec spec = row<double>(name, OptionType::kDouble, group, help, field);
  spec.min = min;
  spec.min_open = min_open;
  spec.max = max;
  spec.max_open = max_open;
  return spec;
}

std::vector<OptionSpec> make_table() {
  std::vector<OptionSpec> t;
  OptionSpec detector;
  detector.name = "detector";
  detector.type = OptionType::kChoice;
  detector.group = kDetection;
  detector.help =
      "Line segment detector: edlines (ours), opencv-edlines (OpenCV's EdgeDrawing), lsd or fld";
  detector.choices = {"edlines", "opencv-edlines", "lsd", "fld"};
  detector.aliases = {{"scbt-edlines", "edlines"}};
  detector.get = [](const TrackerOptions& o) -> OptionValue { return to_string(o.detector.kind); };
  detector.set = [](TrackerOptions* o, const OptionValue& value) {
    o->detector.kind = parse_line_detector_kind(std::get<std::string>(value));
  };
  t.push_back(detector);
  t.push_back(int_row("gradient_threshold", kDetection, "EDLines gradient threshold (Sobel)", 1,
                      255,
                      [](TrackerOptions& o) -> int& { return o.detector.gradient_threshold; }));
  t.push_back(int_row("anchor_threshold", kDetection, "EDLines anchor threshold", 0, 255,
                      [](TrackerOptions& o) -> int& { return o.detector.anchor_threshold; }));
  t.push_back(double_row("min_line_length", kDetection,
                         "Shortest segment kept (px); <= 0: EDLines derives it from the frame size",
                         -kInf, false, 10000.0, false,
                         [](TrackerOptions& o) -> double& { return o.detector.min_line_length; }));

  t.push_back(double_row(
      "filter_distance", kGrouping,
      "Keep segments whose mean distance to the previous boundary is below this (px)", 0.0, true,
      1000.0, false, [](TrackerOptions& o) -> double& { return o.filter_distance; }));
  t.push_back(int_row("max_segments", kGrouping,
                      "Bound on the work per frame: keep at most this many (the longest) segments "
                      "near the boundary",
                      3, 100000, [](TrackerOptions& o) -> int& { return o.max_segments; }));
  t.push_back(int_row("seed_stride", kGrouping,
                      "BDSP seeds every Nth detected segment (the paper: 2; more is faster)", 1,
                      1000, [](TrackerOptions& o) -> int& { return o.bdsp.seed_stride; }));

  t.push_back(double_row("min_area_similarity", kChoice,
                         "Area similarity to the previous boundary a candidate must exceed", 0.0,
                         false, 1.0, true,
                         [](TrackerOptions& o) -> double& { return o.min_area_similarity; }));
  t.push_back(double_row("shape_weight", kChoice,
                         "Candidates are ranked by exp(w x their change of shape from the recent "
                         "confident boundaries) too, so that a leak into the background costs "
                         "(0: off)",
                         0.0, false, 100.0, false,
                         [](TrackerOptions& o) -> double& { return o.shape_weight; }));

  t.push_back(bool_row("object_memory", kChoice,
                       "Remember the object's outline and edges; a cycle departing from it along "
                       "part of it (an occluder, a leak) gives way to the remembered outline "
                       "fitted to the visible part",
                       [](TrackerOptions& o) -> bool& { return o.object_memory; }));

  OptionSpec predict = bool_row("predict_motion", kCamera,
                                "Search where the boundary's motion (the image motion around it) "
                                "predicts it, not where it was",
                                [](TrackerOptions& o) -> bool& { return o.predict_motion; });
  // What builds on the prediction follows it: on its own it would do nothing (check()).
  predict.set = [](TrackerOptions* o, const OptionValue& value) {
    const bool on = std::get<bool>(value);
    o->predict_motion = on;
    o->measure_motion = on;
    o->confirm_motion = on;
    o->fall_back_unmoved = on;
    o->gate_sustained_shrink = on;
  };
  t.push_back(predict);
  t.push_back(bool_row("recover_by_motion", kCamera,
                       "When nothing qualifies, search again where image motion moved the boundary",
                       [](TrackerOptions& o) -> bool& { return o.recover_by_motion; }));
  t.push_back(bool_row("normalize_exposure", kCamera,
                       "Stretch the grey levels of a dim or low-contrast frame before line "
                       "detection, as an automatic gain would",
                       [](TrackerOptions& o) -> bool& { return o.exposure.normalize; }));
  t.push_back(bool_row("adapt_to_blur", kCamera,
                       "Lower the EDLines thresholds by the edge spread measured across the "
                       "boundary (defocus, motion blur)",
                       [](TrackerOptions& o) -> bool& { return o.blur.adapt; }));
  t.push_back(bool_row("smooth_noisy_frames", kCamera,
                       "Smooth a noisy camera's search window before line detection as its noise "
                       "calls for",
                       [](TrackerOptions& o) -> bool& { return o.smooth_noisy_frames; }));

  t.push_back(bool_row("loss_handling", kLoss,
                       "Mark frames uncertain or lost by their confidence, hold the last confident "
                       "boundary while lost and search the frame for the object",
                       [](TrackerOptions& o) -> bool& { return o.loss.enabled; }));
  return t;
}

std::string number_text(double value) {
  if (std::isnan(value)) return "nan";
  char text[40];
  std::snprintf(text, sizeof(text), "%.10g", value);
  return text;
}

std::string quoted(const std::string& text) { return "'" + text + "'"; }

bool parse_number(const std::string& text, double* out);

// The value as the message's "got ...": text quoted unless it reads as a number, so that a
// command line's "2" and a config file's 2 are reported alike.
std::string got_text(const OptionValue& value) {
  if (const auto* text = std::get_if<std::string>(&value)) {
    double number = 0.0;
    return parse_number(*text, &number) ? format_option_value(number) : quoted(*text);
  }
  return format_option_value(value);
}

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// The whole of `text` as a number (surrounding blanks allowed).
bool parse_number(const std::string& text, double* out) {
  const size_t begin = text.find_first_not_of(" \t");
  if (begin == std::string::npos) return false;
  const size_t end = text.find_last_not_of(" \t") + 1;
  const std::string body = text.substr(begin, end - begin);
  char* stop = nullptr;
  *out = std::strtod(body.c_str(), &stop);
  return stop == body.c_str() + body.size();
}

bool in_range(const OptionSpec& spec, double x) {
  const bool above = spec.min_open ? x > spec.min : x >= spec.min;
  const bool below = spec.max_open ? x < spec.max : x <= spec.max;
  return above && below;  // false for NaN
}

[[noreturn]] void fail(const OptionSpec& spec, const std::string& what, const OptionValue& value,
                       bool wrong_kind) {
  const std::string message = spec.name + " must be " + what + ", got " + got_text(value);
  if (wrong_kind) throw OptionTypeError(message);
  throw std::invalid_argument(message);
}

std::string range_phrase(const OptionSpec& spec) {
  if (spec.min == -kInf) return "<= " + number_text(spec.max);
  if (spec.max == kInf) return ">= " + number_text(spec.min);
  return "in " + spec.range_text();
}

OptionValue check_number(const OptionSpec& spec, const OptionValue& value) {
  const bool whole = spec.type == OptionType::kInt;
  const std::string kind = spec.expected();
  double x = 0.0;
  if (const auto* i = std::get_if<long long>(&value)) {
    x = static_cast<double>(*i);
  } else if (const auto* d = std::get_if<double>(&value)) {
    x = *d;
  } else if (const auto* text = std::get_if<std::string>(&value)) {
    if (!parse_number(*text, &x)) fail(spec, kind, value, true);
  } else {
    fail(spec, kind, value, true);
  }
  if (whole && std::isfinite(x) && x != std::floor(x)) fail(spec, kind, x, false);
  if (!in_range(spec, x)) fail(spec, range_phrase(spec), whole ? OptionValue(x) : x, false);
  if (whole) return static_cast<long long>(x);
  return x;
}

OptionValue check_bool(const OptionSpec& spec, const OptionValue& value) {
  if (const auto* b = std::get_if<bool>(&value)) return *b;
  if (const auto* i = std::get_if<long long>(&value)) {
    if (*i == 0 || *i == 1) return *i == 1;
  } else if (const auto* text = std::get_if<std::string>(&value)) {
    const std::string t = lower(*text);
    if (t == "true" || t == "1" || t == "yes" || t == "on") return true;
    if (t == "false" || t == "0" || t == "no" || t == "off") return false;
  }
  fail(spec, "true or false", value, !std::holds_alternative<long long>(value));
}

OptionValue check_choice(const OptionSpec& spec, const OptionValue& value) {
  const std::string what = spec.expected();
  const auto* text = std::get_if<std::string>(&value);
  if (!text) fail(spec, what, value, true);
  for (const std::string& choice : spec.choices) {
    if (*text == choice) return choice;
  }
  for (const auto& [alias, choice] : spec.aliases) {
    if (*text == alias) return choice;
  }
  fail(spec, what, value, false);
}

// A config file's text as OpenCV's FileStorage reads it: YAML needs its "%YAML:1.0" directive.
std::string storage_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::invalid_argument(path + ": cannot open for reading");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  std::string text = buffer.str();
  if (text.size() > (1u << 20)) throw std::invalid_argument(path + ": larger than 1 MiB");
  const size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "{}";
  if (text[first] != '{' && text.compare(first, 5, "%YAML") != 0) {
    text = (text.compare(first, 3, "---") == 0 ? "%YAML:1.0\n" : "%YAML:1.0\n---\n") + text;
  }
  return text;
}

}  // namespace

std::string OptionSpec::flag() const {
  std::string dashed = name;
  std::replace(dashed.begin(), dashed.end(), '_', '-');
  return "--" + dashed;
}

std::string OptionSpec::type_name() const {
  switch (type) {
    case OptionType::kBool:
      return "bool";
    case OptionType::kInt:
      return "int";
    case OptionType::kDouble:
      return "float";
    case OptionType::kChoice:
      return "choice";
  }
  return "?";
}

std::string OptionSpec::expected() const {
  switch (type) {
    case OptionType::kBool:
      return "true or false";
    case OptionType::kInt:
      return "a whole number";
    case OptionType::kDouble:
      return "a number";
    case OptionType::kChoice:
      return "one of " + range_text();
  }
  return "";
}

std::string OptionSpec::range_text() const {
  switch (type) {
    case OptionType::kBool:
      return "true or false";
    case OptionType::kInt:
      return number_text(min) + ".." + number_text(max);
    case OptionType::kDouble:
      if (min == -kInf) return "<= " + number_text(max);
      if (max == kInf) return ">= " + number_text(min);
      return std::string(min_open ? "(" : "[") + number_text(min) + ", " + number_text(max) +
             (max_open ? ")" : "]");
    case OptionType::kChoice: {
      std::string text;
      for (const std::string& choice : choices) text += (text.empty() ? "" : ", ") + choice;
      return text;
    }
  }
  return "";
}

const std::vector<OptionSpec>& tracker_option_table() {
  static const std::vector<OptionSpec> table = make_table();
  return table;
}

const OptionSpec* find_tracker_option(const std::string& name) {
  for (const OptionSpec& spec : tracker_option_table()) {
    if (spec.name == name) return &spec;
  }
  return nullptr;
}

OptionValue check_option_value(const OptionSpec& spec, const OptionValue& value) {
  switch (spec.type) {
    case OptionType::kBool:
      return check_bool(spec, value);
    case OptionType::kInt:
    case OptionType::kDouble:
      return check_number(spec, value);
    case OptionType::kChoice:
      return check_choice(spec, value);
  }
  return value;
}

void set_tracker_option(TrackerOptions* options, const std::string& name,
                        const OptionValue& value) {
  const OptionSpec* spec = find_tracker_option(name);
  if (!spec) throw std::invalid_argument("unknown option " + quoted(name));
  spec->set(options, check_option_value(*spec, value));
}

void check_user_options(const TrackerOptions& options) {
  for (const OptionSpec& spec : tracker_option_table()) check_option_value(spec, spec.get(options));
}

std::string format_option_value(const OptionValue& value) {
  if (const auto* b = std::get_if<bool>(&value)) return *b ? "true" : "false";
  if (const auto* i = std::get_if<long long>(&value)) return std::to_string(*i);
  if (const auto* d = std::get_if<double>(&value)) return number_text(*d);
  return std::get<std::string>(value);
}

std::string tracker_options_repr(const TrackerOptions& options) {
  std::string text = "TrackerOptions(";
  bool first = true;
  for (const OptionSpec& spec : tracker_option_table()) {
    const OptionValue value = spec.get(options);
    std::string shown = format_option_value(value);
    if (spec.type == OptionType::kBool) shown = std::get<bool>(value) ? "True" : "False";
    if (spec.type == OptionType::kChoice) shown = quoted(shown);
    // Python's repr of a float keeps a decimal point.
    if (spec.type == OptionType::kDouble && shown.find_first_of(".en") == std::string::npos) {
      shown += ".0";
    }
    text += (first ? "" : ", ") + spec.name + "=" + shown;
    first = false;
  }
  return text + ")";
}

void read_tracker_options_file(const std::string& path, TrackerOptions* options) {
  const std::string text = storage_text(path);
  cv::FileStorage storage;
  try {
    storage.open(text, cv::FileStorage::READ | cv::FileStorage::MEMORY);
  } catch (const cv::Exception&) {
    throw std::invalid_argument(path + ": not a YAML or JSON mapping of option names to values");
  }
  const cv::FileNode root = storage.root();
  if (!storage.isOpened() || !(root.isMap() || root.empty() || root.isNone())) {
    throw std::invalid_argument(path + ": not a YAML or JSON mapping of option names to values");
  }
  TrackerOptions read = *options;
  for (const cv::FileNode& node : root) {
    const std::string name = node.name();
    OptionValue value;
    if (node.isInt()) {
      value = static_cast<long long>(static_cast<int>(node));
    } else if (node.isReal()) {
      value = static_cast<double>(node);
    } else if (node.isString()) {
      value = node.string();
    } else {
      throw std::invalid_argument(path + ": " + name + " must be a single value");
    }
    try {
      set_tracker_option(&read, name, value);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(path + ": " + e.what());
    }
  }
  *options = read;
}

std::string tracker_options_text(const TrackerOptions& options, bool json) {
  std::string text = json ? "{\n" : "";
  const auto& table = tracker_option_table();
  for (size_t i = 0; i < table.size(); ++i) {
    const OptionSpec& spec = table[i];
    std::string value = format_option_value(spec.get(options));
    if (json) {
      if (spec.type == OptionType::kChoice) value = "\"" + value + "\"";
      text += "  \"" + spec.name + "\": " + value + (i + 1 < table.size() ? ",\n" : "\n");
    } else {
      text += spec.name + ": " + value + "\n";
    }
  }
  return json ? text + "}\n" : text;
}

}  // namespace scbt
