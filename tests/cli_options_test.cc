// The option table walked through the command line and config files: every user option is
// accepted as a flag and as a YAML and JSON key, and each bad value is rejected by all three with
// the library's own message (python/tests/test_options.py walks the Python side, ros/test the
// ROS parameters).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli_test_util.h"
#include "scbt/tracker/option_table.h"

namespace scbt {
namespace {

namespace fs = std::filesystem;
using cli_test::fresh_test_dir;
using cli_test::read_file;

struct Outcome {
  int exit_code = -1;
  std::string out;
  std::string err;
};

Outcome run(const fs::path& dir, const std::string& args) {
  const std::string command = "cd '" + dir.string() + "' && '" + std::string(SCBT_BINARY) + "' " +
                              args + " > out.txt 2> err.txt";
  const int status = std::system(command.c_str());
  Outcome r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 1000 + WTERMSIG(status);
  r.out = read_file(dir / "out.txt");
  r.err = read_file(dir / "err.txt");
  return r;
}

void write(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// A valid value of `spec` other than its default, as text.
std::string other_value(const OptionSpec& spec) {
  const OptionValue value = spec.get(TrackerOptions());
  switch (spec.type) {
    case OptionType::kBool:
      return std::get<bool>(value) ? "false" : "true";
    case OptionType::kInt: {
      const long long v = std::get<long long>(value);
      return std::to_string(v == static_cast<long long>(spec.max) ? v - 1 : v + 1);
    }
    case OptionType::kDouble: {
      const double v = std::get<double>(value);
      const double other = v + 0.25 < spec.max ? v + 0.25 : v - 0.25;
      return format_option_value(other);
    }
    case OptionType::kChoice:
      return std::get<std::string>(value) == spec.choices[0] ? spec.choices[1] : spec.choices[0];
  }
  return "";
}

// Values `spec` must refuse, as text: past each finite bound, a fraction for a whole number,
// words where a number or a switch belongs.
std::vector<std::string> bad_values(const OptionSpec& spec) {
  switch (spec.type) {
    case OptionType::kBool:
      return {"maybe", "2"};
    case OptionType::kChoice:
      return {"nosuch", "7"};
    case OptionType::kInt:
      return {format_option_value(spec.min - 1), format_option_value(spec.max + 1), "2.5", "abc"};
    case OptionType::kDouble: {
      std::vector<std::string> bad = {"abc", "nan"};
      if (std::isfinite(spec.min))
        bad.push_back(format_option_value(spec.min - (spec.min_open ? 0 : 1)));
      if (std::isfinite(spec.max))
        bad.push_back(format_option_value(spec.max + (spec.max_open ? 0 : 1)));
      return bad;
    }
  }
  return {};
}

// The library's message for `text` given to `spec`.
std::string library_message(const OptionSpec& spec, const std::string& text) {
  try {
    check_option_value(spec, text);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

// How a config file writes `text`: numbers and words as they are (YAML reads them as numbers or
// strings), JSON quoting what is not a number.
std::string json_value(const std::string& text) {
  char* end = nullptr;
  std::strtod(text.c_str(), &end);
  const bool number = !text.empty() && *end == '\0' && text != "nan";
  return number ? text : "\"" + text + "\"";
}

class CliOptionsTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = fresh_test_dir("scbt_cli_options"); }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(CliOptionsTest, TableIsSmallAndWellFormed) {
  const auto& table = tracker_option_table();
  EXPECT_GE(table.size(), 10u);
  EXPECT_LE(table.size(), 16u);
  const TrackerOptions defaults;
  EXPECT_NO_THROW(check_user_options(defaults));
  for (const OptionSpec& spec : table) {
    EXPECT_EQ(find_tracker_option(spec.name), &spec);
    EXPECT_FALSE(spec.help.empty()) << spec.name;
    EXPECT_FALSE(spec.group.empty()) << spec.name;
    EXPECT_EQ(spec.name.find('-'), std::string::npos) << spec.name;
    EXPECT_NE(other_value(spec), format_option_value(spec.get(defaults))) << spec.name;
  }
  EXPECT_EQ(find_tracker_option("shape_weight")->flag(), "--shape-weight");
  EXPECT_EQ(find_tracker_option("confidence_bias"), nullptr);
}

// --print-config shows the defaults, so that a config file can start from them.
TEST_F(CliOptionsTest, PrintConfigShowsEveryDefault) {
  const Outcome r = run(dir_, "track --print-config");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, tracker_options_text(TrackerOptions()));
  for (const OptionSpec& spec : tracker_option_table()) {
    EXPECT_NE(r.out.find(spec.name + ": "), std::string::npos) << spec.name;
  }
}

TEST_F(CliOptionsTest, EveryOptionIsAFlagAndAConfigKey) {
  for (const OptionSpec& spec : tracker_option_table()) {
    const std::string value = other_value(spec);
    TrackerOptions expected;
    set_tracker_option(&expected, spec.name, value);
    const std::string want = tracker_options_text(expected);

    const Outcome flag = run(dir_, "track " + spec.flag() + " " + value + " --print-config");
    EXPECT_EQ(flag.exit_code, 0) << spec.name << ": " << flag.err;
    EXPECT_EQ(flag.out, want) << spec.flag() << " " << value;

    write(dir_ / "options.yaml", spec.name + ": " + value + "\n");
    const Outcome yaml = run(dir_, "eval --config options.yaml --print-config");
    EXPECT_EQ(yaml.exit_code, 0) << spec.name << ": " << yaml.err;
    EXPECT_EQ(yaml.out, want) << "YAML " << spec.name << ": " << value;

    write(dir_ / "options.json", "{\"" + spec.name + "\": " + json_value(value) + "}");
    const Outcome json = run(dir_, "demo --config options.json --print-config");
    EXPECT_EQ(json.exit_code, 0) << spec.name << ": " << json.err;
    EXPECT_EQ(json.out, want) << "JSON " << spec.name << ": " << value;
  }
}

TEST_F(CliOptionsTest, EveryBadValueIsRefusedWithTheSameMessage) {
  for (const OptionSpec& spec : tracker_option_table()) {
    for (const std::string& bad : bad_values(spec)) {
      const std::string message = library_message(spec, bad);
      ASSERT_NE(message, "") << spec.name << " accepted " << bad;
      EXPECT_EQ(message.rfind(spec.name + " must be ", 0), 0u) << message;

      const Outcome flag = run(dir_, "track " + spec.flag() + " " + bad + " --print-config");
      EXPECT_EQ(flag.exit_code, 2) << spec.flag() << " " << bad;
      EXPECT_EQ(flag.err, "scbt: error: " + message + "\n") << spec.flag() << " " << bad;

      write(dir_ / "bad.yaml", spec.name + ": " + bad + "\n");
      const Outcome yaml = run(dir_, "track --config bad.yaml --print-config");
      EXPECT_EQ(yaml.exit_code, 2) << "YAML " << spec.name << ": " << bad;
      EXPECT_EQ(yaml.err, "scbt: error: bad.yaml: " + message + "\n") << "YAML " << bad;

      write(dir_ / "bad.json", "{\"" + spec.name + "\": " + json_value(bad) + "}");
      const Outcome json = run(dir_, "track --config bad.json --print-config");
      EXPECT_EQ(json.exit_code, 2) << "JSON " << spec.name << ": " << bad;
      EXPECT_EQ(json.err, "scbt: error: bad.json: " + message + "\n") << "JSON " << bad;
    }
  }
}

// The flags override the config file, whatever their order on the command line.
TEST_F(CliOptionsTest, FlagsOverrideTheConfigFile) {
  write(dir_ / "options.yaml",
        "---\n# as rosparam writes them\nshape_weight: 2\nseed_stride: 3  # faster\n"
        "predict_motion: false\n");
  const Outcome r = run(dir_, "track --shape-weight 1.5 --config options.yaml --print-config");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("shape_weight: 1.5\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("seed_stride: 3\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("predict_motion: false\n"), std::string::npos) << r.out;
}

TEST_F(CliOptionsTest, ConfigFileErrorsNameTheFile) {
  write(dir_ / "typo.yaml", "shape_wieght: 2\n");
  Outcome r = run(dir_, "track --config typo.yaml --print-config");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "scbt: error: typo.yaml: unknown option 'shape_wieght'\n");

  write(dir_ / "broken.json", "{\"shape_weight\": [1, 2");
  r = run(dir_, "track --config broken.json --print-config");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("broken.json: not a YAML or JSON mapping"), std::string::npos) << r.err;

  write(dir_ / "list.yaml", "shape_weight: [1, 2]\n");
  r = run(dir_, "track --config list.yaml --print-config");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "scbt: error: list.yaml: shape_weight must be a single value\n");

  r = run(dir_, "track --config missing.yaml --print-config");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "scbt: error: missing.yaml: cannot open for reading\n");
}

// -o is track's results file: the commands that write a folder take --out only, and say so.
TEST_F(CliOptionsTest, FolderCommandsRefuseDashO) {
  for (const std::string command : {"eval", "demo"}) {
    const Outcome r = run(dir_, command + " -o out --print-config");
    EXPECT_EQ(r.exit_code, 2) << command;
    EXPECT_EQ(r.err, "scbt: error: " + command +
                         " writes a folder: give it as --out DIR (-o is track's results file)\n");
  }
}

// Options that only act through another are switched with it; on their own they are refused.
TEST(TrackerOptionsCheck, RefusesSwitchesThatWouldDoNothing) {
  TrackerOptions options;
  set_tracker_option(&options, "predict_motion", false);
  EXPECT_FALSE(options.measure_motion || options.confirm_motion || options.fall_back_unmoved ||
               options.gate_sustained_shrink);
  EXPECT_NO_THROW(options.check());
  options.gate_sustained_shrink = true;
  try {
    options.check();
    ADD_FAILURE() << "gate_sustained_shrink without predict_motion accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "gate_sustained_shrink acts only with predict_motion: turn it off too");
  }

  TrackerOptions adaptive;
  adaptive.adaptive_thresholds.enabled = true;
  EXPECT_THROW(adaptive.check(), std::invalid_argument);  // smooth_noisy_frames
  adaptive.smooth_noisy_frames = false;
  EXPECT_THROW(adaptive.check(), std::invalid_argument);  // retry_weak_frames
  adaptive.adaptive_thresholds.retry_weak_frames = false;
  EXPECT_NO_THROW(adaptive.check());
}

TEST(TrackerOptionsCheck, ReportsUserOptionsInTheTablesWords) {
  TrackerOptions options;
  options.shape_weight = 101.0;
  try {
    options.check();
    ADD_FAILURE() << "shape_weight 101 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "shape_weight must be in [0, 100], got 101");
  }
}

TEST(TrackerOptionsRepr, ListsEveryOptionAsPythonWouldWriteIt) {
  const std::string repr = tracker_options_repr(TrackerOptions());
  EXPECT_EQ(repr.rfind("TrackerOptions(detector='edlines', gradient_threshold=36, ", 0), 0u)
      << repr;
  EXPECT_NE(repr.find("filter_distance=20.0, "), std::string::npos) << repr;
  EXPECT_NE(repr.find("predict_motion=True"), std::string::npos) << repr;
}

}  // namespace
}  // namespace scbt
