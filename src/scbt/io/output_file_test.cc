// OutputFile and OutputSet: a regular file appears complete on commit or not at all; devices,
// FIFOs and symlinks are written through, never replaced.
#include "scbt/io/output_file.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <opencv2/core.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>

#include "scbt/io/output_set.h"

namespace scbt {
namespace {

namespace fs = std::filesystem;

class OutputFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("scbt_output_file_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
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

TEST_F(OutputFileTest, AppearsOnlyOnCommit) {
  const fs::path path = dir_ / "result.txt";
  {
    OutputFile file(path.string());
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

TEST_F(OutputFileTest, UncommittedLeavesNothing) {
  const fs::path path = dir_ / "result.txt";
  std::string temporary;
  {
    OutputFile file(path.string());
    temporary = file.temporary_path();
    file.stream() << "partial";
  }
  EXPECT_FALSE(fs::exists(path));
  EXPECT_FALSE(fs::exists(temporary));
  EXPECT_EQ(count_entries(), 0);
}

TEST_F(OutputFileTest, ExistingFileSurvivesAnAbandonedWrite) {
  const fs::path path = dir_ / "result.txt";
  std::ofstream(path) << "old content\n";
  {
    OutputFile file(path.string());
    file.stream() << "new but unfinished";
    EXPECT_EQ(read(path), "old content\n");
  }
  EXPECT_EQ(read(path), "old content\n");
  EXPECT_EQ(count_entries(), 1);
  // Committing replaces it.
  {
    OutputFile file(path.string());
    file.stream() << "new\n";
    file.commit();
  }
  EXPECT_EQ(read(path), "new\n");
  EXPECT_EQ(count_entries(), 1);
}

TEST_F(OutputFileTest, UnwritableFolderNamesThePath) {
  const fs::path path = dir_ / "missing_folder" / "result.txt";
  try {
    OutputFile file(path.string());
    ADD_FAILURE() << "opened a file in a missing folder";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
}

TEST_F(OutputFileTest, AFolderIsRefusedBeforeAnythingIsWritten) {
  const fs::path path = dir_ / "occupied";
  fs::create_directories(path / "inside");
  try {
    OutputFile file(path.string());
    ADD_FAILURE() << "opened a folder as an output";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("is a folder"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_directory(path / "inside"));
  EXPECT_EQ(count_entries(), 1);
}

TEST_F(OutputFileTest, ADeviceNodeIsWrittenInPlace) {
  const fs::path node = dir_ / "null";
  if (::mknod(node.c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0) {
    GTEST_SKIP() << "mknod not permitted here";
  }
  {
    OutputFile file(node.string());
    EXPECT_EQ(file.target().kind, OutputKind::kInPlace);
    EXPECT_EQ(file.temporary_path(), "");
    file.stream() << "results\n";
    file.commit();
  }
  EXPECT_TRUE(fs::is_character_file(fs::symlink_status(node)));
  EXPECT_EQ(count_entries(), 1);
}

TEST_F(OutputFileTest, ASymlinkToADeviceStaysASymlink) {
  const fs::path link = dir_ / "out.txt";
  fs::create_symlink("/dev/null", link);
  {
    OutputFile file(link.string());
    file.stream() << "results\n";
    file.commit();
  }
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link)));
  EXPECT_EQ(fs::read_symlink(link), "/dev/null");
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

TEST_F(OutputFileTest, ASymlinkToARegularFileReplacesItsTarget) {
  fs::create_directories(dir_ / "real");
  std::ofstream(dir_ / "real" / "results.txt") << "old\n";
  const fs::path link = dir_ / "results.txt";
  fs::create_symlink("real/results.txt", link);
  {
    OutputFile file(link.string());
    EXPECT_EQ(fs::path(file.temporary_path()).parent_path(), dir_ / "real");
    file.stream() << "new\n";
    file.commit();
  }
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link)));
  EXPECT_EQ(read(dir_ / "real" / "results.txt"), "new\n");
  EXPECT_EQ(count_entries(), 2);  // the link and the folder, no temporary file
}

TEST_F(OutputFileTest, ADanglingSymlinkCreatesItsTarget) {
  const fs::path link = dir_ / "results.txt";
  fs::create_symlink("made.txt", link);
  {
    OutputFile file(link.string());
    file.stream() << "new\n";
    file.commit();
  }
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link)));
  EXPECT_EQ(read(dir_ / "made.txt"), "new\n");
}

TEST_F(OutputFileTest, PermissionsOfAnExistingFileAreKept) {
  const fs::path path = dir_ / "private.txt";
  std::ofstream(path) << "old\n";
  fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write);
  {
    OutputFile file(path.string());
    file.stream() << "new\n";
    file.commit();
  }
  EXPECT_EQ(fs::status(path).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write);
  EXPECT_EQ(read(path), "new\n");
}

TEST_F(OutputFileTest, TwoWritersOfOnePathUseTheirOwnTemporaryFiles) {
  const fs::path path = dir_ / "shared.txt";
  OutputFile first(path.string());
  OutputFile second(path.string());
  EXPECT_NE(first.temporary_path(), second.temporary_path());
  EXPECT_NE(first.temporary_path().find(".tmp-" + std::to_string(::getpid())), std::string::npos);
  first.stream() << "first\n";
  second.stream() << "second\n";
  first.commit();
  EXPECT_EQ(read(path), "first\n");
  second.commit();
  EXPECT_EQ(read(path), "second\n");
}

TEST_F(OutputFileTest, AFullDeviceIsAWriteError) {
  if (!fs::is_character_file("/dev/full")) GTEST_SKIP() << "no /dev/full";
  OutputFile file("/dev/full");
  file.stream() << "results\n";
  try {
    file.commit();
    ADD_FAILURE() << "writing to /dev/full succeeded";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/dev/full: write failed"), std::string::npos) << e.what();
  }
}

// A FIFO's reader gets each record as it is ended, long before the commit; when the reader
// goes away the writer learns it (EPIPE) instead of dying of SIGPIPE or failing.
TEST_F(OutputFileTest, AFifoIsStreamedLiveAndItsReaderMayLeave) {
  const fs::path fifo = dir_ / "live";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  struct sigaction ignore {
  }, old{};
  ignore.sa_handler = SIG_IGN;
  sigaction(SIGPIPE, &ignore, &old);
  std::string first_line;
  std::thread reader([&] {
    const int fd = ::open(fifo.c_str(), O_RDONLY);
    char c = 0;
    while (::read(fd, &c, 1) == 1 && c != '\n') first_line += c;
    ::close(fd);  // leaves after one line
  });
  {
    OutputFile file(fifo.string());  // blocks until the reader opens it
    file.stream() << "1 2 3\n";
    file.end_record();
    reader.join();
    EXPECT_EQ(first_line, "1 2 3");
    for (int i = 0; i < 100000 && !file.reader_gone(); ++i) {
      file.stream() << "more\n";
      file.end_record();
    }
    EXPECT_TRUE(file.reader_gone());
    EXPECT_NO_THROW(file.commit());
  }
  sigaction(SIGPIPE, &old, nullptr);
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(fifo)));
}

// One failing output keeps every other one from replacing its old file.
TEST_F(OutputFileTest, ASetIsCommittedOnlyWhenEveryOutputIsComplete) {
  if (!fs::is_character_file("/dev/full")) GTEST_SKIP() << "no /dev/full";
  const fs::path kept = dir_ / "results.txt";
  std::ofstream(kept) << "old\n";
  {
    OutputSet outputs;
    outputs.add_file(kept.string()).stream() << "new\n";
    outputs.add_file("/dev/full").stream() << "stats\n";
    EXPECT_THROW(outputs.commit(), std::runtime_error);
  }
  EXPECT_EQ(read(kept), "old\n");
  EXPECT_EQ(count_entries(), 1);
}

TEST_F(OutputFileTest, AVideoNeedsAContainerExtension) {
  EXPECT_THROW(VideoOutput((dir_ / "f%02d.jpg").string(), 25), std::invalid_argument);
  EXPECT_THROW(VideoOutput("-", 25), std::invalid_argument);
  EXPECT_EQ(count_entries(), 0);
}

TEST_F(OutputFileTest, AVideoIsPublishedWithAllItsFrames) {
  for (const char* name : {"out.avi", "out.mp4", "out.mkv"}) {
    SCOPED_TRACE(name);
    const fs::path path = dir_ / name;
    {
      OutputSet outputs;
      VideoOutput& video = outputs.add_video(path.string(), 10);
      for (int i = 0; i < 5; ++i) video.write(cv::Mat(48, 64, CV_8UC3, cv::Scalar(i * 40, 0, 0)));
      EXPECT_FALSE(fs::exists(path));
      outputs.commit();
    }
    cv::VideoCapture check(path.string(), cv::CAP_FFMPEG);
    EXPECT_EQ(static_cast<int>(check.get(cv::CAP_PROP_FRAME_COUNT)), 5);
    fs::remove(path);
  }
  EXPECT_EQ(count_entries(), 0);
}

TEST_F(OutputFileTest, AVideoWithoutItsLastFramesFailsTheCommit) {
  const fs::path path = dir_ / "cut.avi";
  std::ofstream(dir_ / "results.txt") << "old\n";
  // Files may not grow beyond 6 KiB (a full disk): the AVI header fits, the frames do not.
  struct rlimit old_limit {};
  getrlimit(RLIMIT_FSIZE, &old_limit);
  struct sigaction ignore {
  }, old_action{};
  ignore.sa_handler = SIG_IGN;
  sigaction(SIGXFSZ, &ignore, &old_action);
  struct rlimit limit = old_limit;
  limit.rlim_cur = 6144;
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &limit), 0);
  std::string message;
  {
    OutputSet outputs;
    outputs.add_file((dir_ / "results.txt").string()).stream() << "new\n";
    VideoOutput& video = outputs.add_video(path.string(), 10);
    cv::Mat noise(120, 160, CV_8UC3);
    for (int i = 0; i < 10; ++i) {
      cv::randu(noise, 0, 255);
      video.write(noise);
    }
    try {
      outputs.commit();
    } catch (const std::runtime_error& e) {
      message = e.what();
    }
  }
  setrlimit(RLIMIT_FSIZE, &old_limit);
  sigaction(SIGXFSZ, &old_action, nullptr);
  EXPECT_NE(message.find("cut.avi: write failed"), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(path));
  EXPECT_EQ(read(dir_ / "results.txt"), "old\n");
  EXPECT_EQ(count_entries(), 1);
}

TEST_F(OutputFileTest, AnEmptyRunPublishesNoVideo) {
  const fs::path path = dir_ / "out.avi";
  {
    OutputSet outputs;
    outputs.add_video(path.string(), 10);
    outputs.commit();
  }
  EXPECT_EQ(count_entries(), 0);
}

TEST_F(OutputFileTest, AnAbandonedFrameFolderLeavesNothing) {
  {
    OutputSet outputs;
    FrameFolderOutput& frames = outputs.add_frame_folder((dir_ / "frames").string());
    frames.write(1, cv::Mat(8, 8, CV_8UC3, cv::Scalar::all(0)));
    EXPECT_TRUE(fs::is_directory(dir_ / "frames"));
  }
  EXPECT_EQ(count_entries(), 0);
}

TEST(Printable, ControlCharactersCannotStartANewLine) {
  EXPECT_EQ(printable("a\nscbt: error: b\x1b[2J"), "a\\nscbt: error: b\\x1b[2J");
}

TEST(CsvField, QuotedOnlyWhenItWouldSplitTheRecord) {
  EXPECT_EQ(csv_field("jpeg:95"), "jpeg:95");
  EXPECT_EQ(csv_field("occlude:0.3,2,bar"), "\"occlude:0.3,2,bar\"");
  EXPECT_EQ(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(csv_field("two\nlines\r"), "\"two lines \"");
}

}  // namespace
}  // namespace scbt
