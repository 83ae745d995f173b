// The node's tracker parameters walked through the option table: every option is a parameter of
// the same name, and every bad value is refused with the table's message (as the CLI, config files
// and Python refuse it: tests/cli_options_test.cc, python/tests/test_options.py).
#include "scbt_ros/node_options.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "scbt/tracker/option_table.h"

namespace scbt::ros_node {
namespace {

using XmlRpc::XmlRpcValue;

// Parameters as a map, under the node's private namespace /scbt.
TrackerOptions read(const std::map<std::string, XmlRpcValue>& parameters) {
  return tracker_options_from_parameters(
      [&parameters](const std::string& name, XmlRpcValue* value) {
        const auto found = parameters.find(name);
        if (found == parameters.end()) return false;
        *value = found->second;
        return true;
      },
      [](const std::string& name) { return "/scbt/" + name; });
}

// What `read` throws for `parameters` ("" when it accepts them).
std::string refusal(const std::map<std::string, XmlRpcValue>& parameters) {
  try {
    read(parameters);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

// A valid parameter value of `spec` other than its default, and the same as the table takes it.
XmlRpcValue other_value(const OptionSpec& spec) {
  const OptionValue value = spec.get(TrackerOptions());
  switch (spec.type) {
    case OptionType::kBool:
      return XmlRpcValue(!std::get<bool>(value));
    case OptionType::kInt: {
      const int v = static_cast<int>(std::get<long long>(value));
      return XmlRpcValue(v == static_cast<int>(spec.max) ? v - 1 : v + 1);
    }
    case OptionType::kDouble: {
      const double v = std::get<double>(value);
      return XmlRpcValue(v + 0.25 < spec.max ? v + 0.25 : v - 0.25);
    }
    case OptionType::kChoice:
      return XmlRpcValue(std::get<std::string>(value) == spec.choices[0] ? spec.choices[1]
                                                                         : spec.choices[0]);
  }
  return XmlRpcValue();
}

OptionValue as_option_value(XmlRpcValue& value) {
  switch (value.getType()) {
    case XmlRpcValue::TypeBoolean:
      return static_cast<bool>(value);
    case XmlRpcValue::TypeInt:
      return static_cast<long long>(static_cast<int>(value));
    case XmlRpcValue::TypeDouble:
      return static_cast<double>(value);
    default:
      return static_cast<std::string>(value);
  }
}

// Parameter values `spec` must refuse: past each finite bound, a fraction for a whole number,
// text where a number or a switch belongs, a number where a name belongs.
std::vector<XmlRpcValue> bad_values(const OptionSpec& spec) {
  switch (spec.type) {
    case OptionType::kBool:
      return {XmlRpcValue(2), XmlRpcValue("maybe")};
    case OptionType::kChoice:
      return {XmlRpcValue("nosuch"), XmlRpcValue(7)};
    case OptionType::kInt:
      return {XmlRpcValue(static_cast<int>(spec.min) - 1),
              XmlRpcValue(static_cast<int>(spec.max) + 1), XmlRpcValue(2.5), XmlRpcValue("abc")};
    case OptionType::kDouble: {
      std::vector<XmlRpcValue> bad = {XmlRpcValue("abc"), XmlRpcValue(std::nan(""))};
      if (std::isfinite(spec.min)) bad.emplace_back(spec.min - (spec.min_open ? 0.0 : 1.0));
      if (std::isfinite(spec.max)) bad.emplace_back(spec.max + (spec.max_open ? 0.0 : 1.0));
      return bad;
    }
  }
  return {};
}

TEST(NodeOptions, EveryTableOptionIsAParameter) {
  EXPECT_EQ(refusal({}), "");
  const std::vector<std::string> names = node_parameter_names();
  for (const OptionSpec& spec : tracker_option_table()) {
    EXPECT_NE(std::find(names.begin(), names.end(), spec.name), names.end()) << spec.name;
    XmlRpcValue value = other_value(spec);
    TrackerOptions expected;
    set_tracker_option(&expected, spec.name, as_option_value(value));
    const TrackerOptions got = read({{spec.name, value}});
    EXPECT_EQ(tracker_options_text(got), tracker_options_text(expected)) << spec.name;
    EXPECT_NE(tracker_options_text(got), tracker_options_text(TrackerOptions())) << spec.name;
  }
}

TEST(NodeOptions, EveryBadValueIsRefusedWithTheTablesMessage) {
  for (const OptionSpec& spec : tracker_option_table()) {
    for (XmlRpcValue bad : bad_values(spec)) {
      std::string message;
      try {
        check_option_value(spec, as_option_value(bad));
      } catch (const std::invalid_argument& e) {
        message = e.what();
      }
      ASSERT_NE(message, "") << spec.name << " accepted " << bad.toXml();
      EXPECT_EQ(refusal({{spec.name, bad}}), "parameter /scbt/" + spec.name + ": " + message);
    }
  }
  XmlRpcValue list;
  list[0] = 1;
  EXPECT_EQ(refusal({{"shape_weight", list}}),
            "parameter /scbt/shape_weight: shape_weight must be a number, got a list");
}

// The launch file passes every option on (its argument named as the parameter).
TEST(NodeOptions, LaunchFileHasAnArgumentPerOption) {
  std::ifstream file(SCBT_LAUNCH_FILE);
  std::stringstream text;
  text << file.rdbuf();
  ASSERT_FALSE(text.str().empty()) << SCBT_LAUNCH_FILE;
  for (const OptionSpec& spec : tracker_option_table()) {
    EXPECT_NE(text.str().find("<arg name=\"" + spec.name + "\" default=\"\"/>"), std::string::npos)
        << spec.name;
    EXPECT_NE(
        text.str().find("<param name=\"" + spec.name + "\" value=\"$(arg " + spec.name + ")\""),
        std::string::npos)
        << spec.name;
  }
}

}  // namespace
}  // namespace scbt::ros_node
