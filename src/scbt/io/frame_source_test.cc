// Numbered image folders and frame sources, on folders written by the test.
#include "scbt/io/frame_source.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>
#include <stdexcept>
#include <string>

#include "scbt/testing/avi_test_util.h"

namespace scbt {
namespace {

namespace fs = std::filesystem;

class FrameSourceTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("scbt_frame_source_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // An image whose every pixel is `value`, so frames can be told apart after decoding.
  void write_image(const std::string& name, int value) {
    const cv::Mat image(24, 32, CV_8UC3, cv::Scalar(value, value, value));
    ASSERT_TRUE(cv::imwrite((dir_ / name).string(), image));
  }
  void write_text(const std::string& name, const std::string& content) {
    std::ofstream(dir_ / name, std::ios::binary) << content;
  }
  std::string folder() const { return dir_.string(); }

  // Expects a std::runtime_error whose message contains every needle.
  template <typename Fn>
  void expect_error(Fn fn, const std::vector<std::string>& needles) {
    try {
      fn();
      ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& e) {
      for (const std::string& needle : needles) {
        EXPECT_NE(std::string(e.what()).find(needle), std::string::npos)
            << "'" << e.what() << "' does not mention '" << needle << "'";
      }
    }
  }

  fs::path dir_;
};

TEST_F(FrameSourceTest, ListsNumericallyNotLexically) {
  // 8, 9, 10, 11 sort as 10, 11, 8, 9 lexically; mixed widths and extensions.
  write_image("9.png", 9);
  write_image("10.png", 10);
  write_image("008.png", 8);
  write_image("11.bmp", 11);
  write_text("notes.txt", "not an image");
  write_text("12a.png", "not numbered");
  const std::vector<std::string> files = list_numbered_images(folder());
  ASSERT_EQ(files.size(), 4u);
  EXPECT_EQ(fs::path(files[0]).filename(), "008.png");
  EXPECT_EQ(fs::path(files[1]).filename(), "9.png");
  EXPECT_EQ(fs::path(files[2]).filename(), "10.png");
  EXPECT_EQ(fs::path(files[3]).filename(), "11.bmp");
}

TEST_F(FrameSourceTest, ManyFramesInOrder) {
  for (int i = 1; i <= 120; ++i) write_text(std::to_string(i) + ".jpg", "x");
  const std::vector<std::string> files = list_numbered_images(folder());
  ASSERT_EQ(files.size(), 120u);
  for (int i = 0; i < 120; ++i) {
    EXPECT_EQ(fs::path(files[i]).stem(), std::to_string(i + 1));
  }
}

TEST_F(FrameSourceTest, ListErrorsNameTheFolder) {
  expect_error([&] { list_numbered_images(folder()); }, {folder(), "no numbered images"});
  write_text("0001.jpg", "x");
  write_text("0002.jpg", "x");
  write_text("0004.jpg", "x");
  expect_error([&] { list_numbered_images(folder()); }, {folder(), "gap", "0002.jpg"});
  write_text("0003.jpg", "x");
  EXPECT_EQ(list_numbered_images(folder()).size(), 4u);
  write_text("3.png", "x");  // the same number twice
  expect_error([&] { list_numbered_images(folder()); }, {folder(), "3"});
}

TEST_F(FrameSourceTest, AFolderNamedLikeAFrameIsAnError) {
  write_text("0002.jpg", "x");
  fs::create_directory(dir_ / "0001.jpg");
  expect_error([&] { list_numbered_images(folder()); },
               {"0001.jpg", "named like a frame but not a regular file"});
}

TEST_F(FrameSourceTest, NumberingMustStartAtZeroOrOne) {
  write_image("0005.png", 10);
  write_image("0006.png", 20);
  expect_error([&] { open_frame_source(folder()); },
               {folder(), "numbering starts at 0005.png, not at 0 or 1"});
  write_image("0000.png", 10);
  write_image("0001.png", 10);
  write_image("0002.png", 10);
  write_image("0003.png", 10);
  write_image("0004.png", 10);
  EXPECT_EQ(open_frame_source(folder())->frame_count(), 7);
}

TEST_F(FrameSourceTest, ReadsAFolderOfPngs) {
  write_image("0001.png", 10);
  write_image("0002.png", 120);
  write_image("0003.png", 250);
  const std::unique_ptr<FrameSource> source = open_frame_source(folder());
  EXPECT_EQ(source->frame_count(), 3);
  cv::Mat frame;
  for (int value : {10, 120, 250}) {
    ASSERT_TRUE(source->read(&frame));
    ASSERT_FALSE(frame.empty());
    EXPECT_EQ(frame.size(), cv::Size(32, 24));
    EXPECT_EQ(frame.at<cv::Vec3b>(5, 5)[0], value);
  }
  EXPECT_NE(source->current_name().find("0003.png"), std::string::npos);
  EXPECT_FALSE(source->read(&frame));
  EXPECT_FALSE(source->read(&frame));
}

TEST_F(FrameSourceTest, NonexistentPathNamesIt) {
  const std::string missing = (dir_ / "no_such_video.avi").string();
  expect_error([&] { open_frame_source(missing); }, {missing});
  const std::string missing_folder = (dir_ / "no_such_folder").string();
  expect_error([&] { open_frame_source(missing_folder + "/"); }, {missing_folder});
}

TEST_F(FrameSourceTest, CorruptImageNamesTheFile) {
  write_image("1.png", 50);
  // JPEG magic, then junk (the length is the literal's, no terminating NUL).
  static const char kFakeJpeg[] = "\xff\xd8 this is not really a jpeg \x01\x02\x03";
  write_text("2.jpg", std::string(kFakeJpeg, sizeof(kFakeJpeg) - 1));
  write_image("3.png", 60);
  const std::unique_ptr<FrameSource> source = open_frame_source(folder());
  cv::Mat frame;
  ASSERT_TRUE(source->read(&frame));
  expect_error([&] { source->read(&frame); }, {"2.jpg"});
}

TEST_F(FrameSourceTest, NotAVideoFile) {
  write_text("clip.avi", "garbage, not a video");
  const std::string path = (dir_ / "clip.avi").string();
  expect_error([&] { open_frame_source(path); }, {path});
}

TEST_F(FrameSourceTest, AFrameTheVideoReaderSkipsIsReportedInPlace) {
  const fs::path path = dir_ / "dropped.avi";
  std::vector<cv::Mat> frames;
  for (int i = 1; i <= 10; ++i) frames.emplace_back(48, 64, CV_8UC3, cv::Scalar::all(20 * i));
  ASSERT_EQ(write_avi_with_a_dropped_frame(path.string(), frames, 5), "");
  const std::unique_ptr<FrameSource> source = open_frame_source(path.string());
  ASSERT_EQ(source->frame_count(), 10);
  cv::Mat frame;
  for (int i = 1; i <= 10; ++i) {
    SCOPED_TRACE("frame " + std::to_string(i));
    if (i == 5) {
      expect_error([&] { source->read(&frame); }, {"frame 5", "skipped by the video decoder"});
      continue;
    }
    ASSERT_TRUE(source->read(&frame));
    EXPECT_NEAR(cv::mean(frame)[0], 20 * i, 4);  // the frame that belongs here, not the next
  }
  EXPECT_FALSE(source->read(&frame));
}

}  // namespace
}  // namespace scbt
