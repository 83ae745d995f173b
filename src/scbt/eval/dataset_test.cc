#include "scbt/eval/dataset.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>

namespace scbt {
namespace {
namespace fs = std::filesystem;

class DatasetTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() /
            ("scbt-dataset-test-" + std::to_string(::getpid()) + "-" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root_);
    fs::create_directories(root_ / "OriginalVideosAVI");
    fs::create_directories(root_ / "GroundTruthByPolygons");
  }
  void TearDown() override { fs::remove_all(root_); }

  // A sequence with `frames` tiny images and a matching ground truth file (either may be left
  // out to build incomplete layouts).
  void add_sequence(const std::string& name, int frames, bool with_truth = true) {
    const fs::path folder = root_ / "OriginalVideosAVI" / name;
    fs::create_directories(folder);
    for (int i = 1; i <= frames; ++i) {
      char file[16];
      std::snprintf(file, sizeof(file), "%04d.jpg", i);
      cv::imwrite((folder / file).string(), cv::Mat(8, 8, CV_8UC3, cv::Scalar(i, i, i)));
    }
    if (with_truth) {
      std::ofstream((root_ / "GroundTruthByPolygons" / (name + "_TrackingGroundTruth.txt")))
          << "3 1 1 5 1 3 5\n";
    }
  }

  fs::path root_;
};

TEST_F(DatasetTest, ListsCompleteSequencesSortedByName) {
  add_sequence("Zeta", 2);
  add_sequence("Alpha", 3);
  add_sequence("NoTruth", 2, false);
  std::ofstream(root_ / "GroundTruthByPolygons" / "NoFrames_TrackingGroundTruth.txt") << "\n";
  std::ofstream(root_ / "GroundTruthByPolygons" / "readme.txt") << "\n";
  const std::vector<DatasetSequence> sequences = list_dataset_sequences(root_.string());
  ASSERT_EQ(sequences.size(), 2u);
  EXPECT_EQ(sequences[0].name, "Alpha");
  EXPECT_EQ(sequences[1].name, "Zeta");
  EXPECT_EQ(fs::path(sequences[0].frames), root_ / "OriginalVideosAVI" / "Alpha");
  EXPECT_EQ(fs::path(sequences[1].ground_truth),
            root_ / "GroundTruthByPolygons" / "Zeta_TrackingGroundTruth.txt");
}

TEST_F(DatasetTest, SelectsInTheGivenOrderAndNamesUnknownSequences) {
  add_sequence("Bowl", 1);
  add_sequence("Cup", 1);
  const auto selected = select_dataset_sequences(root_.string(), {"Cup", "Bowl"});
  ASSERT_EQ(selected.size(), 2u);
  EXPECT_EQ(selected[0].name, "Cup");
  EXPECT_EQ(selected[1].name, "Bowl");
  EXPECT_EQ(select_dataset_sequences(root_.string(), {}).size(), 2u);
  try {
    select_dataset_sequences(root_.string(), {"Bowel"});
    FAIL() << "unknown sequence accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'Bowel'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("Bowl, Cup"), std::string::npos) << e.what();
  }
  EXPECT_THROW(select_dataset_sequences(root_.string(), {"Cup", "Cup"}), std::invalid_argument);
}

TEST_F(DatasetTest, RejectsFoldersNotLaidOutAsTheDataset) {
  EXPECT_THROW(list_dataset_sequences((root_ / "missing").string()), std::runtime_error);
  EXPECT_THROW(list_dataset_sequences(root_.string()), std::runtime_error);  // no sequence
  fs::remove_all(root_ / "GroundTruthByPolygons");
  add_sequence("Bowl", 1, false);
  EXPECT_THROW(list_dataset_sequences(root_.string()), std::runtime_error);
}

TEST(ResultsPath, IsTheSequenceNameWithTxtInsideTheFolder) {
  EXPECT_EQ(fs::path(results_path("out/bdsp", "Bowl")), fs::path("out/bdsp/Bowl.txt"));
}

}  // namespace
}  // namespace scbt
