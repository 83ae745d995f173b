// check_no_overwrite: outputs that would overwrite an input or each other are refused up front.
#include "scbt/io/same_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace scbt {
namespace {

namespace fs = std::filesystem;

class SameFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("scbt_same_file_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "seq");
    std::ofstream(dir_ / "seq" / "0001.jpg") << "x";
    std::ofstream(dir_ / "gt.txt") << "3 1 1 5 1 1 5\n";
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string at(const std::string& name) const { return (dir_ / name).string(); }

  // The message of the refusal, or "" when the paths are accepted.
  std::string refusal(const std::vector<NamedPath>& outputs,
                      const std::vector<NamedPath>& folders = {}) const {
    try {
      check_no_overwrite({{"INPUT", at("seq")}, {"--init", at("gt.txt")}}, outputs, folders);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  }
  fs::path dir_;
};

TEST_F(SameFileTest, DistinctOutputsAreAccepted) {
  EXPECT_EQ(refusal({{"-o", at("out.txt")}, {"--csv", at("out.csv")}, {"--video", at("a.avi")}},
                    {{"--frames-out", at("frames")}}),
            "");
}

TEST_F(SameFileTest, TheInitFileAsResultsIsRefusedNamingBoth) {
  const std::string message = refusal({{"-o", at("gt.txt")}});
  EXPECT_NE(message.find("-o " + at("gt.txt") + " is the same file as --init " + at("gt.txt")),
            std::string::npos)
      << message;
}

TEST_F(SameFileTest, AnotherNameForTheSameFileIsRefused) {
  fs::create_hard_link(dir_ / "gt.txt", dir_ / "hard.txt");
  fs::create_symlink("gt.txt", dir_ / "soft.txt");
  EXPECT_NE(refusal({{"-o", at("hard.txt")}}), "");
  EXPECT_NE(refusal({{"-o", at("soft.txt")}}), "");
  EXPECT_NE(refusal({{"-o", at("./seq/../gt.txt")}}), "");
}

TEST_F(SameFileTest, AFileInsideTheInputFolderIsRefused) {
  EXPECT_NE(refusal({{"-o", at("seq/0001.jpg")}}).find("is inside the input folder"),
            std::string::npos);
  EXPECT_NE(refusal({{"--csv", at("seq/new.csv")}}), "");
}

TEST_F(SameFileTest, TwoOutputsNamingOneFileAreRefused) {
  EXPECT_NE(refusal({{"-o", at("x")}, {"--csv", at("x")}}).find("--csv " + at("x")),
            std::string::npos);
  EXPECT_NE(refusal({{"-o", "-"}, {"--csv", "-"}}), "");
}

TEST_F(SameFileTest, CharacterDevicesMayBeNamedTwice) {
  EXPECT_EQ(refusal({{"-o", "/dev/null"}, {"--csv", "/dev/null"}}), "");
}

TEST_F(SameFileTest, TheInputFolderAsFrameFolderIsRefused) {
  EXPECT_NE(refusal({}, {{"--frames-out", at("seq")}}), "");
  EXPECT_NE(refusal({{"-o", at("frames/0001.jpg")}}, {{"--frames-out", at("frames")}}), "");
}

TEST_F(SameFileTest, TheInputVideoIsRefused) {
  std::ofstream(dir_ / "in.avi") << "x";
  EXPECT_THROW(check_no_overwrite({{"INPUT", at("in.avi")}}, {{"--video", at("in.avi")}}, {}),
               std::invalid_argument);
  // A camera index names no file.
  EXPECT_NO_THROW(check_no_overwrite({{"INPUT", "0"}}, {{"-o", at("0")}}, {}));
}

}  // namespace
}  // namespace scbt
