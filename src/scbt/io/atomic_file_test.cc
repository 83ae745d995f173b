// AtomicFile: the final file appears complete on commit, or not at all.
#include "scbt/io/atomic_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace scbt {
namespace {

namespace fs = std::filesystem;

class AtomicFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("scbt_atomic_file_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  static std::string read(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    std::ostringstream content;
    content << file.rdbuf();
    return content.str();
  }
  int count_entries() const {
    int n = 0;
    for (const auto& entry : fs::directory_iterator(dir_)) {
      (void)entry;
      ++n;
    }
    return n;
  }

  fs::path dir_;
};

TEST_F(AtomicFileTest, AppearsOnlyOnCommit) {
  const fs::path path = dir_ / "result.txt";
  {
    AtomicFile file(path.string());
    EXPECT_EQ(file.path(), path.string());
    EXPECT_NE(file.temporary_path(), path.string());
    file.stream() << "line 1\n" << 42 << "\n";
    file.stream().flush();
    EXPECT_FALSE(fs::exists(path));
    EXPECT_TRUE(fs::exists(file.temporary_path()));
    file.commit();
    EXPECT_TRUE(fs::exists(path));
    EXPECT_FALSE(fs::exists(file.temporary_path()));
  }
  EXPECT_EQ(read(path), "line 1\n42\n");
  EXPECT_EQ(count_entries(), 1);  // no temporary left behind
}

TEST_F(AtomicFileTest, UncommittedLeavesNothing) {
  const fs::path path = dir_ / "result.txt";
  std::string temporary;
  {
    AtomicFile file(path.string());
    temporary = file.temporary_path();
    file.stream() << "partial";
  }
  EXPECT_FALSE(fs::exists(path));
  EXPECT_FALSE(fs::exists(temporary));
  EXPECT_EQ(count_entries(), 0);
}

TEST_F(AtomicFileTest, ExistingFileSurvivesAnAbandonedWrite) {
  const fs::path path = dir_ / "result.txt";
  std::ofstream(path) << "old content\n";
  {
    AtomicFile file(path.string());
    file.stream() << "new but unfinished";
    EXPECT_EQ(read(path), "old content\n");
  }
  EXPECT_EQ(read(path), "old content\n");
  EXPECT_EQ(count_entries(), 1);
  // Committing replaces it.
  {
    AtomicFile file(path.string());
    file.stream() << "new\n";
    file.commit();
  }
  EXPECT_EQ(read(path), "new\n");
  EXPECT_EQ(count_entries(), 1);
}

TEST_F(AtomicFileTest, UnwritableFolderNamesThePath) {
  const fs::path path = dir_ / "missing_folder" / "result.txt";
  try {
    AtomicFile file(path.string());
    ADD_FAILURE() << "opened a file in a missing folder";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
}

TEST_F(AtomicFileTest, CommitOntoAFolderFailsAndCleansUp) {
  const fs::path path = dir_ / "occupied";
  fs::create_directories(path / "inside");  // a non-empty folder: rename cannot replace it
  std::string temporary;
  {
    AtomicFile file(path.string());
    temporary = file.temporary_path();
    file.stream() << "data";
    EXPECT_THROW(file.commit(), std::runtime_error);
  }
  EXPECT_TRUE(fs::is_directory(path));
  EXPECT_FALSE(fs::exists(temporary));
}

}  // namespace
}  // namespace scbt
