// Test support: what a test needs from the machine (the public dataset, a program such as
// roslaunch). Outside CI a test whose need is missing is skipped, with the reason printed; under
// CI=true (the CI job sets it) the same test fails instead, so that a CI machine that lost the
// dataset or a tool cannot pass by running less. Every test with such a need goes through
// SCBT_REQUIRE; programs outside gtest (ros_test_main, interactive_xvfb_test.py, the ROS
// placeholder test) apply the same rule with ci_requires_everything().
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

namespace scbt {

// True when the environment has CI=true.
inline bool ci_requires_everything() {
  const char* ci = std::getenv("CI");
  return ci != nullptr && std::strcmp(ci, "true") == 0;
}

// The dataset folder named by SCBT_DATASET (ctest sets it from the CMake cache's
// SCBT_DATASET_DIR) when it holds OriginalVideosAVI/ and GroundTruthByPolygons/; else empty.
inline std::string test_dataset_folder() {
  const char* dataset = std::getenv("SCBT_DATASET");
  if (dataset == nullptr || *dataset == '\0') return {};
  const std::filesystem::path root(dataset);
  if (!std::filesystem::is_directory(root / "OriginalVideosAVI") ||
      !std::filesystem::is_directory(root / "GroundTruthByPolygons")) {
    return {};
  }
  return root.string();
}

// The value of SCBT_DATASET, quoted, for messages.
inline std::string test_dataset_setting() {
  const char* dataset = std::getenv("SCBT_DATASET");
  return dataset == nullptr ? std::string("SCBT_DATASET not set")
                            : "SCBT_DATASET=\"" + std::string(dataset) + "\"";
}

}  // namespace scbt

// In a test body: when `available` is false, fails the test under CI=true and skips it otherwise,
// both with `what` (a stream expression naming what is missing and how to get it).
#define SCBT_REQUIRE(available, what)                                               \
  do {                                                                              \
    if (!(available)) {                                                             \
      if (::scbt::ci_requires_everything()) {                                       \
        GTEST_FAIL() << "CI=true and this test's requirement is missing: " << what; \
      } else {                                                                      \
        GTEST_SKIP() << "skipped (under CI=true this fails): missing " << what;     \
      }                                                                             \
    }                                                                               \
  } while (false)

// In a test body: the dataset folder, or a skip (a failure under CI=true) when it is absent.
#define SCBT_REQUIRE_DATASET(folder_variable)                                                 \
  const std::string folder_variable = ::scbt::test_dataset_folder();                          \
  SCBT_REQUIRE(!folder_variable.empty(),                                                      \
               "the public dataset (" << ::scbt::test_dataset_setting()                       \
                                      << "; configure with -DSCBT_DATASET_DIR=DIR, a folder " \
                                         "with OriginalVideosAVI/ and GroundTruthByPolygons/)")
