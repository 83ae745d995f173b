#include "scbt_ros/node_options.h"

#include <ros/node_handle.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "scbt/geometry/polygon_io.h"
#include "scbt/tracker/option_table.h"

namespace scbt::ros_node {
namespace {

using XmlRpc::XmlRpcValue;

// Every read goes through this: a parameter read but missing from node_parameter_names() would
// be warned about as unknown though it is used.
const std::string& known(const std::string& name) {
  static const std::vector<std::string> names = node_parameter_names();
  if (std::find(names.begin(), names.end(), name) == names.end()) {
    throw std::logic_error("parameter ~" + name + " is read but not listed as known");
  }
  return name;
}

const char* type_name(XmlRpcValue::Type type) {
  switch (type) {
    case XmlRpcValue::TypeBoolean:
      return "a boolean";
    case XmlRpcValue::TypeInt:
      return "an integer";
    case XmlRpcValue::TypeDouble:
      return "a number";
    case XmlRpcValue::TypeString:
      return "a string";
    case XmlRpcValue::TypeArray:
      return "a list";
    case XmlRpcValue::TypeStruct:
      return "a dictionary";
    default:
      return "an unsupported value";
  }
}

std::invalid_argument wrong_type(const ros::NodeHandle& node, const std::string& name,
                                 const char* expected, XmlRpcValue::Type got) {
  return std::invalid_argument("parameter " + node.resolveName(name) + " must be " + expected +
                               ", got " + type_name(got));
}

// Numbers given as integers (`_filter_distance:=20`) are accepted where a double belongs.
bool to_double(XmlRpcValue& value, double* out) {
  if (value.getType() == XmlRpcValue::TypeDouble) {
    *out = static_cast<double>(value);
    return true;
  }
  if (value.getType() == XmlRpcValue::TypeInt) {
    *out = static_cast<int>(value);
    return true;
  }
  return false;
}

void read_double(const ros::NodeHandle& node, const std::string& name, double* out) {
  XmlRpcValue value;
  if (!node.getParam(known(name), value)) return;
  if (!to_double(value, out)) throw wrong_type(node, name, "a number", value.getType());
  if (!std::isfinite(*out)) {
    throw std::invalid_argument("parameter " + node.resolveName(name) + " must be finite");
  }
}

void read_int(const ros::NodeHandle& node, const std::string& name, int* out) {
  XmlRpcValue value;
  if (!node.getParam(known(name), value)) return;
  if (value.getType() != XmlRpcValue::TypeInt) {
    throw wrong_type(node, name, "an integer", value.getType());
  }
  *out = static_cast<int>(value);
}

void read_bool(const ros::NodeHandle& node, const std::string& name, bool* out) {
  XmlRpcValue value;
  if (!node.getParam(known(name), value)) return;
  if (value.getType() != XmlRpcValue::TypeBoolean) {
    throw wrong_type(node, name, "true or false", value.getType());
  }
  *out = static_cast<bool>(value);
}

// "[1, 2.5, 3]" or "1 2.5 3" as numbers.
std::vector<double> parse_numbers(const std::string& name, std::string text) {
  const size_t open = text.find_first_not_of(" \t");
  const size_t close = text.find_last_not_of(" \t");
  if (open != std::string::npos && text[open] == '[' && text[close] == ']') {
    text = text.substr(open + 1, close - open - 1);
  }
  std::replace(text.begin(), text.end(), ',', ' ');
  std::istringstream in(text);
  std::vector<double> numbers;
  std::string token;
  while (in >> token) {
    size_t used = 0;
    double x = 0.0;
    try {
      x = std::stod(token, &used);
    } catch (const std::exception&) {
    }
    if (used != token.size() || !std::isfinite(x)) {
      throw std::invalid_argument("parameter " + name + " must be a list of numbers, got '" +
                                  token + "' in it");
    }
    numbers.push_back(x);
  }
  return numbers;
}

std::optional<std::vector<double>> read_numbers(const ros::NodeHandle& node,
                                                const std::string& name) {
  XmlRpcValue value;
  if (!node.getParam(known(name), value)) return std::nullopt;
  // roscpp keeps a command-line `_init_box:=[1, 2, 3, 4]` as a string: parse it as the list.
  if (value.getType() == XmlRpcValue::TypeString) {
    return parse_numbers(node.resolveName(name), static_cast<std::string>(value));
  }
  if (value.getType() != XmlRpcValue::TypeArray) {
    throw wrong_type(node, name, "a list of numbers", value.getType());
  }
  std::vector<double> numbers(value.size());
  for (int i = 0; i < value.size(); ++i) {
    if (!to_double(value[i], &numbers[i]) || !std::isfinite(numbers[i])) {
      throw std::invalid_argument("parameter " + node.resolveName(name) +
                                  " must be a list of finite numbers (item " + std::to_string(i) +
                                  " is not)");
    }
  }
  return numbers;
}

// The value as the option table takes it; a list or a dictionary is none.
std::optional<OptionValue> option_value(XmlRpcValue& value) {
  switch (value.getType()) {
    case XmlRpcValue::TypeBoolean:
      return OptionValue(static_cast<bool>(value));
    case XmlRpcValue::TypeInt:
      return OptionValue(static_cast<long long>(static_cast<int>(value)));
    case XmlRpcValue::TypeDouble:
      return OptionValue(static_cast<double>(value));
    case XmlRpcValue::TypeString:
      return OptionValue(static_cast<std::string>(value));
    default:
      return std::nullopt;
  }
}

}  // namespace

std::vector<std::string> node_parameter_names() {
  std::vector<std::string> names;
  for (const OptionSpec& spec : tracker_option_table()) names.push_back(spec.name);
  for (const char* own :
       {"use_depth", "min_depth", "max_depth", "sync_queue_size", "init_polygon", "init_box",
        // Read by image_transport: which transport (raw, compressed, ...).
        "image_transport"}) {
    names.push_back(own);
  }
  return names;
}

TrackerOptions tracker_options_from_parameters(
    const ParameterLookup& lookup, const std::function<std::string(const std::string&)>& resolve) {
  TrackerOptions options;
  for (const OptionSpec& spec : tracker_option_table()) {
    XmlRpcValue value;
    if (!lookup(spec.name, &value)) continue;
    const std::optional<OptionValue> given = option_value(value);
    if (!given) {
      throw std::invalid_argument("parameter " + resolve(spec.name) + ": " + spec.name +
                                  " must be " + spec.expected() + ", got " +
                                  type_name(value.getType()));
    }
    try {
      set_tracker_option(&options, spec.name, *given);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("parameter " + resolve(spec.name) + ": " + e.what());
    }
  }
  return options;
}

cv::Rect pixel_box(double x, double y, double width, double height) {
  for (const double value : {x, y, width, height}) {
    // Rounded into an int below: a value beyond one would wrap or saturate into another box.
    if (!(std::abs(value) <= std::numeric_limits<int>::max())) {
      std::ostringstream text;
      text.precision(15);
      text << value;
      throw std::invalid_argument("a box value (" + text.str() + ") is out of range (at most " +
                                  std::to_string(std::numeric_limits<int>::max()) + " pixels)");
    }
  }
  const cv::Rect box(cvRound(x), cvRound(y), cvRound(width), cvRound(height));
  if (box.width <= 0 || box.height <= 0) {
    throw std::invalid_argument("a box needs a positive width and height");
  }
  if (box.x < 0 || box.y < 0)
    throw std::invalid_argument("a box must not start left of or above the image");
  return box;
}

void NodeOptions::check() const {
  tracker.check();
  depth.check();
  if (sync_queue_size < 1) throw std::invalid_argument("sync_queue_size must be at least 1");
  if (init_polygon) check_boundary_polygon(*init_polygon);
}

NodeOptions read_node_options(const ros::NodeHandle& node) {
  NodeOptions options;
  options.tracker = tracker_options_from_parameters(
      [&node](const std::string& name, XmlRpcValue* value) { return node.getParam(name, *value); },
      [&node](const std::string& name) { return node.resolveName(name); });
  read_bool(node, "use_depth", &options.use_depth);
  read_double(node, "min_depth", &options.depth.min_depth);
  read_double(node, "max_depth", &options.depth.max_depth);
  read_int(node, "sync_queue_size", &options.sync_queue_size);

  const auto polygon = read_numbers(node, "init_polygon");
  const auto box = read_numbers(node, "init_box");
  if (polygon && box) {
    throw std::invalid_argument("set either " + node.resolveName("init_polygon") + " or " +
                                node.resolveName("init_box") + ", not both");
  }
  if (polygon) {
    if (polygon->size() < 6 || polygon->size() % 2 != 0) {
      throw std::invalid_argument("parameter " + node.resolveName("init_polygon") +
                                  " must be [x1, y1, x2, y2, x3, y3, ...] (at least 3 points)");
    }
    Polygon p;
    for (size_t i = 0; i < polygon->size(); i += 2)
      p.emplace_back((*polygon)[i], (*polygon)[i + 1]);
    options.init_polygon = p;
  }
  if (box) {
    if (box->size() != 4) {
      throw std::invalid_argument("parameter " + node.resolveName("init_box") +
                                  " must be [x, y, width, height]");
    }
    try {
      options.init_box = pixel_box((*box)[0], (*box)[1], (*box)[2], (*box)[3]);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("parameter " + node.resolveName("init_box") + ": " + e.what());
    }
  }
  options.check();
  return options;
}

std::vector<std::string> unknown_parameters(const ros::NodeHandle& node) {
  std::vector<std::string> all;
  std::vector<std::string> unknown;
  if (!node.getParamNames(all)) return unknown;
  const std::string prefix = node.getNamespace() + "/";
  for (const std::string& name : all) {
    if (name.rfind(prefix, 0) != 0) continue;
    const std::string local = name.substr(prefix.size());
    const std::string head = local.substr(0, local.find('/'));
    const std::vector<std::string> known = node_parameter_names();
    if (std::find(known.begin(), known.end(), head) == known.end()) unknown.push_back(name);
  }
  return unknown;
}

}  // namespace scbt::ros_node
