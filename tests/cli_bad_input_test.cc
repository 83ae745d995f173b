// Table-driven test of `scbt track` on bad input: every case builds its input in a fresh folder,
// runs the built binary and checks the exit code, the one-line "scbt: error:" / "scbt: warning:"
// message and what was (or was not) written.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "scbt/geometry/polygon_io.h"
#include "scbt/synthetic/scene.h"

#ifndef SCBT_BINARY
#error "SCBT_BINARY must name the scbt executable"
#endif

namespace scbt {
namespace {

namespace fs = std::filesystem;

std::string read_file(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

void write_file(const fs::path& path, const std::string& content) {
  std::ofstream(path, std::ios::binary) << content;
}

struct RunResult {
  int exit_code = -1;
  std::string err;  // stderr
};

// Runs scbt with `args` (already shell-quoted) in `dir`, capturing stderr.
RunResult run_scbt(const fs::path& dir, const std::string& args) {
  const fs::path err = dir / "stderr.txt";
  const std::string command = "cd '" + dir.string() + "' && '" + std::string(SCBT_BINARY) + "' " +
                              args + " 2> '" + err.string() + "' > /dev/null";
  const int status = std::system(command.c_str());
  RunResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 1000 + WTERMSIG(status);
  result.err = read_file(err);
  return result;
}

// A small synthetic sequence whose first-frame boundary is known.
struct Sequence {
  std::vector<cv::Mat> frames;  // 8-bit BGR
  Polygon truth;
};

const Sequence& sequence() {
  static const Sequence seq = [] {
    SceneOptions options;
    options.size = cv::Size(160, 120);
    options.object_size = 30;
    options.clutter_strokes = 10;
    options.shape = SceneShape::kBox;
    MotionOptions motion;
    motion.start.translation = {80, 60};
    motion.amplitude = {15, 10};
    motion.rotation_amplitude = 0.1;
    motion.scale_amplitude = 0.05;
    motion.period = 40;
    Sequence s;
    for (SceneFrame& f : render_clip(options, smooth_motion_path(motion, 8))) {
      if (s.truth.empty()) s.truth = f.truth;
      s.frames.push_back(f.image);
    }
    return s;
  }();
  return seq;
}

std::string frame_name(int index) {
  char name[16];
  std::snprintf(name, sizeof(name), "%04d.png", index);
  return name;
}

// Writes the sequence as dir/seq/0001.png ... and dir/init.txt.
void write_sequence(const fs::path& dir) {
  fs::create_directories(dir / "seq");
  for (size_t i = 0; i < sequence().frames.size(); ++i) {
    ASSERT_TRUE(cv::imwrite((dir / "seq" / frame_name(static_cast<int>(i) + 1)).string(),
                            sequence().frames[i]));
  }
  write_file(dir / "init.txt", format_polygon_line(sequence().truth) + "\n");
}

std::string points_of(const Polygon& polygon) {
  std::string text;
  for (const Point& p : polygon) {
    text += (text.empty() ? "" : " ") + std::to_string(p.x) + "," + std::to_string(p.y);
  }
  return text;
}

struct Case {
  std::string name;
  std::function<void(const fs::path& dir)> setup;  // after the default sequence is written
  std::string args;                                // out.txt is the results file
  int exit_code;
  std::string message;  // must appear in stderr
  int result_lines;     // lines expected in out.txt; -1: out.txt must not exist
};

const std::string kTrack = "track seq --init init.txt -o out.txt -q ";
void no_setup(const fs::path&) {}

std::vector<Case> cases() {
  const int n = static_cast<int>(sequence().frames.size());
  auto recode = [](int flags_depth, int channels) {
    return [flags_depth, channels](const fs::path& dir) {
      for (const fs::directory_entry& e : fs::directory_iterator(dir / "seq")) {
        cv::Mat image = cv::imread(e.path().string(), cv::IMREAD_COLOR);
        if (channels == 1) cv::cvtColor(image, image, cv::COLOR_BGR2GRAY);
        if (channels == 4) cv::cvtColor(image, image, cv::COLOR_BGR2BGRA);
        if (flags_depth == CV_16U) image.convertTo(image, CV_16U, 257.0);
        cv::imwrite(e.path().string(), image);
      }
    };
  };
  auto init_file = [](const std::string& content) {
    return [content](const fs::path& dir) { write_file(dir / "init.txt", content); };
  };
  const Polygon& t = sequence().truth;
  const std::string a = std::to_string(t[0].x) + "," + std::to_string(t[0].y);
  const std::string b = std::to_string(t[1].x) + "," + std::to_string(t[1].y);
  const std::string c = std::to_string(t[2].x) + "," + std::to_string(t[2].y);
  const std::string inline_track = "track seq -o out.txt -q --init-points ";
  return {
      {"baseline colour frames", no_setup, kTrack, 0, "", n},
      {"grey frames", recode(CV_8U, 1), kTrack, 0, "", n},
      {"16-bit frames", recode(CV_16U, 3), kTrack, 0, "", n},
      {"4-channel frames", recode(CV_8U, 4), kTrack, 0, "", n},
      {"missing input", no_setup, "track nowhere --init init.txt -o out.txt", 1,
       "scbt: error: nowhere: no such file or folder", -1},
      {"input neither video, folder nor camera",
       [](const fs::path& dir) { ::mkfifo((dir / "fifo").c_str(), 0600); },
       "track fifo --init init.txt -o out.txt", 1,
       "fifo: neither a video file, an image folder nor a camera index", -1},
      {"video that cannot be opened",
       [](const fs::path& dir) { write_file(dir / "clip.avi", "not a video at all"); },
       "track clip.avi --init init.txt -o out.txt", 1, "clip.avi: cannot open as a video", -1},
      {"folder without images", [](const fs::path& dir) { fs::create_directory(dir / "empty"); },
       "track empty --init init.txt -o out.txt", 1, "no numbered images", -1},
      {"gap in the numbering", [](const fs::path& dir) { fs::remove(dir / "seq" / frame_name(3)); },
       kTrack, 1, "image numbering has a gap after 0002.png", -1},
      {"corrupt frame in the middle: held",
       [](const fs::path& dir) { write_file(dir / "seq" / frame_name(4), "garbage"); }, kTrack, 3,
       "scbt: warning: seq/0004.png: cannot decode image (frame 4); boundary held", n},
      {"truncated frame in the middle: held",
       [](const fs::path& dir) {
         const std::string bytes = read_file(dir / "seq" / frame_name(5));
         write_file(dir / "seq" / frame_name(5), bytes.substr(0, bytes.size() / 2));
       },
       kTrack, 3, "seq/0005.png: truncated image file (frame 5); boundary held", n},
      {"corrupt frame with --on-bad-frame=stop",
       [](const fs::path& dir) { write_file(dir / "seq" / frame_name(4), "garbage"); },
       kTrack + "--on-bad-frame=stop", 1,
       "scbt: error: seq/0004.png: cannot decode image (frame 4; --on-bad-frame=stop)", -1},
      {"corrupt first frame",
       [](const fs::path& dir) { write_file(dir / "seq" / frame_name(1), "garbage"); }, kTrack, 1,
       "seq/0001.png: cannot decode image", -1},
      {"frame size changes",
       [](const fs::path& dir) {
         cv::imwrite((dir / "seq" / frame_name(6)).string(), cv::Mat(100, 100, CV_8UC3));
       },
       kTrack, 3, "seq/0006.png: frame size changed from 160x120 to 100x100 (frame 6)", n},
      {"polygon with 2 points", no_setup, inline_track + "'" + a + " " + b + "'", 2,
       "at least 3 distinct vertices", -1},
      {"polygon repeating a point", no_setup,
       inline_track + "'" + a + " " + b + " " + b + " " + c + "'", 2, "repeats a vertex", -1},
      {"self-intersecting polygon", no_setup, inline_track + "'10,10 100,10 10,90 60,100'", 2,
       "intersects itself", -1},
      {"zero-area polygon", no_setup, inline_track + "'10,10 20,20 30,30 40,40'", 2,
       "encloses no area", -1},
      {"polygon outside the frame", no_setup, inline_track + "'10,10 500,10 500,90'", 2,
       "is outside the 160x120 frame", -1},
      {"NaN in --init-points", no_setup, inline_track + "'10,10 nan,10 50,90'", 2, "not finite",
       -1},
      {"infinity in the polygon file", init_file("3 10 10 inf 10 50 90\n"), kTrack, 1,
       "init.txt:1:", -1},
      {"polygon file with a wrong count", init_file("4 10 10 60 10 50 90\n"), kTrack, 1,
       "init.txt:1:", -1},
      {"polygon file with a non-numeric token", init_file("3 10 10 6O 10 50 90\n"), kTrack, 1,
       "init.txt:1:", -1},
      {"polygon file starting with an empty line", init_file("\n" + points_of(t)), kTrack, 1,
       "init.txt:1:", -1},
      {"polygon file with trailing garbage", init_file(format_polygon_line(t) + " 12 junk\n"),
       kTrack, 1, "init.txt:1:", -1},
      {"polygon file with CRLF line ends", init_file(format_polygon_line(t) + "\r\n\r\n"), kTrack,
       0, "", n},
      {"empty polygon file", init_file(""), kTrack, 1, "init.txt: file is empty", -1},
      {"polygon file with a huge line",
       init_file("3 " + std::string(4 << 20, '7') + " 1 2 3 4 5\n"), kTrack, 1, "init.txt:1:", -1},
      {"missing polygon file", no_setup, "track seq --init none.txt -o out.txt", 1,
       "none.txt: cannot open for reading", -1},
      {"filter distance out of range", no_setup, kTrack + "--filter-distance -1", 2,
       "filter_distance must be in (0, 1000]", -1},
      {"area similarity out of range", no_setup, kTrack + "--min-area-similarity 2", 2,
       "min_area_similarity must be in [0, 1)", -1},
      {"seed stride out of range", no_setup, kTrack + "--seed-stride 0", 2,
       "seed_stride must be in 1..1000, got 0", -1},
      {"max segments out of range", no_setup, kTrack + "--max-segments 1", 2,
       "max_segments must be in 3..100000, got 1", -1},
      {"negative max frames", no_setup, kTrack + "--max-frames -1", 2,
       "--max-frames must be >= 0, got -1", -1},
      {"unknown bad-frame policy", no_setup, kTrack + "--on-bad-frame maybe", 2,
       "scbt: error: ", -1},
      {"non-numeric option value", no_setup, kTrack + "--filter-distance far", 2,
       "scbt: error: ", -1},
      {"unknown option", no_setup, kTrack + "--bogus", 2, "scbt: error: ", -1},
      {"unwritable output folder", no_setup, "track seq --init init.txt -o no/such/out.txt", 1,
       "no/such/out.txt: cannot open for writing", -1},
  };
}

class CliBadInputTest : public ::testing::TestWithParam<size_t> {};

TEST_P(CliBadInputTest, MessageExitCodeAndOutput) {
  const Case c = cases()[GetParam()];
  SCOPED_TRACE(c.name);
  const fs::path dir =
      fs::temp_directory_path() /
      ("scbt_cli_bad_input_" + std::to_string(::getpid()) + "_" + std::to_string(GetParam()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  write_sequence(dir);
  c.setup(dir);
  const RunResult r = run_scbt(dir, c.args);
  // For the record (ctest --verbose): what each bad input got.
  std::printf("[case] %s -> exit %d: %s\n", c.name.c_str(), r.exit_code,
              r.err.empty() ? "(no message)\n" : r.err.c_str());
  EXPECT_EQ(r.exit_code, c.exit_code) << r.err;
  if (!c.message.empty()) {
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
  }
  // An error is exactly one "scbt: error:" line, the last one.
  if (c.exit_code == 1 || c.exit_code == 2) {
    const size_t at = r.err.find("scbt: error: ");
    ASSERT_NE(at, std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\n', at), r.err.size() - 1) << r.err;
  }
  if (c.result_lines < 0) {
    EXPECT_FALSE(fs::exists(dir / "out.txt"));
  } else {
    const std::vector<std::string> lines = read_text_lines((dir / "out.txt").string());
    EXPECT_EQ(static_cast<int>(lines.size()), c.result_lines);
    for (const std::string& line : lines) {
      Polygon polygon;
      std::string error;
      EXPECT_TRUE(try_parse_polygon_line(line, &polygon, &error)) << line << ": " << error;
    }
  }
  // No temporary file is left behind.
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
  }
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Table, CliBadInputTest, ::testing::Range<size_t>(0, cases().size()),
                         [](const ::testing::TestParamInfo<size_t>& info) {
                           std::string name = cases()[info.param].name;
                           for (char& ch : name) {
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           }
                           return name;
                         });

class CliRunTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("scbt_cli_run_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
            std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    write_sequence(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(CliRunTest, FailedRunKeepsTheExistingOutput) {
  write_file(dir_ / "out.txt", "old results\n");
  write_file(dir_ / "seq" / frame_name(3), "garbage");
  const RunResult r = run_scbt(dir_, kTrack + "--on-bad-frame=stop --csv out.csv");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(read_file(dir_ / "out.txt"), "old results\n");
  EXPECT_FALSE(fs::exists(dir_ / "out.csv"));
}

// Hard frames are tracked through (exit 0) and say so in the CSV's note column.
TEST_F(CliRunTest, HardFramesAreNotedInTheCsv) {
  const cv::Mat& like = sequence().frames[0];
  // Frame 3: nothing at all; frame 5: a dense grid of 12 px strokes over the whole frame.
  cv::imwrite((dir_ / "seq" / frame_name(3)).string(), cv::Mat(like.size(), like.type(), 128));
  cv::Mat dense = like.clone();
  for (int y = 4; y < dense.rows - 14; y += 12) {
    for (int x = 4; x < dense.cols - 14; x += 12) {
      const bool across = ((x + y) / 12) % 2 == 0;
      cv::line(dense, {x, y}, {x + (across ? 12 : 0), y + (across ? 0 : 12)}, cv::Scalar(0, 0, 0),
               2);
    }
  }
  cv::imwrite((dir_ / "seq" / frame_name(5)).string(), dense);
  const RunResult r = run_scbt(dir_, kTrack + "--csv out.csv --max-segments 20");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> rows = read_text_lines((dir_ / "out.csv").string());
  ASSERT_EQ(rows.size(), sequence().frames.size());  // header + frames 2..n
  EXPECT_NE(rows[0].find(",note"), std::string::npos);
  EXPECT_EQ(rows[2].rfind("3,1,", 0), 0u) << rows[2];
  EXPECT_NE(rows[2].find("held: no segments"), std::string::npos) << rows[2];
  EXPECT_NE(rows[4].find("segments capped: "), std::string::npos) << rows[4];
}

// SIGTERM / SIGINT mid-run: the frames tracked so far form a complete results file, the run says
// how far it got, and the exit code is 128 + the signal.
void expect_interrupted_cleanly(const fs::path& dir, int signal_number) {
  // A long input: the first frame repeated (copies are cheap; decoding and tracking are not).
  const int frames = 4000;
  for (int i = static_cast<int>(sequence().frames.size()) + 1; i <= frames; ++i) {
    fs::copy_file(dir / "seq" / frame_name(1), dir / "seq" / frame_name(i));
  }
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const std::string err = (dir / "stderr.txt").string();
    if (!std::freopen(err.c_str(), "w", stderr)) ::_exit(127);
    if (::chdir(dir.c_str()) != 0) ::_exit(127);
    ::execl(SCBT_BINARY, SCBT_BINARY, "track", "seq", "--init", "init.txt", "-o", "out.txt", "-q",
            "--csv", "out.csv", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  ::kill(child, signal_number);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
  const std::string err = read_file(dir / "stderr.txt");
  ASSERT_EQ(WEXITSTATUS(status), 128 + signal_number) << err;
  const std::string name = signal_number == SIGINT ? "SIGINT" : "SIGTERM";
  const size_t at = err.find("interrupted by " + name + " after frame ");
  ASSERT_NE(at, std::string::npos) << err;
  const int reached = std::atoi(err.c_str() + at + name.size() + 28);
  EXPECT_GT(reached, 1);
  EXPECT_LT(reached, frames);
  EXPECT_NE(err.find(" of 4000; out.txt holds frames 1.." + std::to_string(reached)),
            std::string::npos)
      << err;
  const std::vector<std::string> lines = read_text_lines((dir / "out.txt").string());
  ASSERT_EQ(static_cast<int>(lines.size()), reached);
  for (const std::string& line : lines) {
    Polygon polygon;
    std::string error;
    EXPECT_TRUE(try_parse_polygon_line(line, &polygon, &error)) << line << ": " << error;
  }
  // The CSV has a header and one row per tracked frame (the first frame has none).
  EXPECT_EQ(static_cast<int>(read_text_lines((dir / "out.csv").string()).size()), reached);
}

TEST_F(CliRunTest, SigtermFlushesAValidResultsFile) { expect_interrupted_cleanly(dir_, SIGTERM); }

TEST_F(CliRunTest, SigintFlushesAValidResultsFile) { expect_interrupted_cleanly(dir_, SIGINT); }

}  // namespace
}  // namespace scbt
