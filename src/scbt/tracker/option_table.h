// The tracker options a user tunes, as one table: name, type, default, range, one-line help and
// group of each. The CLI flags (`--shape-weight`), the Python keyword arguments and
// scbt.TrackerOptions (`shape_weight`), the ROS parameters (`~shape_weight`) and the keys of a
// config file (`shape_weight: 4`) are all made from it, so every interface accepts the same
// options with the same defaults and rejects a bad value with the same message.
//
// The other fields of TrackerOptions are fitted constants and internal switches: the library
// keeps them at their defaults unless a C++ caller sets them.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "scbt/tracker/tracker_options.h"

namespace scbt {

enum class OptionType { kBool, kInt, kDouble, kChoice };

// A value as an interface hands it over: a bool, a whole number, a number or a text. Text is
// parsed for the option's type (a command line's "0.5", "true").
using OptionValue = std::variant<bool, long long, double, std::string>;

// A value of the wrong kind (text where a number belongs): Python raises TypeError for it.
class OptionTypeError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

struct OptionSpec {
  std::string name;  // snake_case: keyword, parameter and config key; the CLI flag is --dashed
  OptionType type = OptionType::kDouble;
  std::string group;  // the heading it is listed under
  std::string help;   // one line
  // kInt, kDouble: the allowed range (an infinite bound is none); open ends exclude the bound.
  double min = 0.0;
  double max = 0.0;
  bool min_open = false;
  bool max_open = false;
  std::vector<std::string> choices;                          // kChoice: the accepted names
  std::vector<std::pair<std::string, std::string>> aliases;  // kChoice: other name -> choice
  std::function<OptionValue(const TrackerOptions&)> get;
  std::function<void(TrackerOptions*, const OptionValue&)> set;  // a checked, normalised value

  std::string flag() const;        // "--shape-weight"
  std::string type_name() const;   // "bool", "int", "float", "choice"
  std::string range_text() const;  // "[0, 100]", "1..1000", "true or false", "edlines, lsd, ..."
  // What a value of the wrong kind is told: "true or false", "a whole number", "a number",
  // "one of edlines, ...".
  std::string expected() const;
};

// The user options in the order they are listed (grouped).
const std::vector<OptionSpec>& tracker_option_table();
// nullptr when `name` is not a user option.
const OptionSpec* find_tracker_option(const std::string& name);

// `value` checked against `spec` and converted to its type (bool, long long, double or the
// choice's canonical name). Throws OptionTypeError for a value of the wrong kind and
// std::invalid_argument for one out of range, both worded "NAME must be ..., got VALUE".
OptionValue check_option_value(const OptionSpec& spec, const OptionValue& value);
// Checks `value` and sets the option. Throws std::invalid_argument for an unknown name
// ("unknown option 'NAME'") and as check_option_value.
void set_tracker_option(TrackerOptions* options, const std::string& name, const OptionValue& value);
// Throws as check_option_value for the first user option of `options` out of its range.
void check_user_options(const TrackerOptions& options);

// "true", "36", "0.9", "edlines" (numbers as %.10g).
std::string format_option_value(const OptionValue& value);
// "TrackerOptions(detector='edlines', gradient_threshold=36, ...)", every user option.
std::string tracker_options_repr(const TrackerOptions& options);

// Reads a config file (YAML or JSON, by its extension, as OpenCV's FileStorage reads them): a
// mapping of option names to values, e.g. `shape_weight: 2.0` / {"predict_motion": false}; the
// options it names are set on `options`, the others kept. Throws std::invalid_argument
// "FILE: MESSAGE" for an unreadable file, an unknown name or a bad value.
void read_tracker_options_file(const std::string& path, TrackerOptions* options);
// Every user option of `options` as such a file: YAML ("name: value" lines), or JSON.
std::string tracker_options_text(const TrackerOptions& options, bool json = false);

}  // namespace scbt
