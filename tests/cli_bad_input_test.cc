// Table-driven test of `scbt track` on bad input: every case builds its input in a fresh folder,
// runs the built binary and checks the exit code, the one-line "scbt: error:" / "scbt: warning:"
// message and what was (or was not) written.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cli_test_util.h"
#include "scbt/geometry/polygon_io.h"
#include "scbt/synthetic/scene.h"
#include "scbt/testing/avi_test_util.h"

namespace scbt {
namespace {

namespace fs = std::filesystem;

void write_file(const fs::path& path, const std::string& content) {
  std::ofstream(path, std::ios::binary) << content;
}

using cli_test::fresh_test_dir;
using cli_test::read_file;
using cli_test::read_text_lines_of;
using cli_test::run_scbt;
using cli_test::RunResult;

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

using Check = std::function<void(const fs::path& dir, const std::string& err)>;

struct Case {
  std::string name;
  std::function<void(const fs::path& dir)> setup;  // after the default sequence is written
  std::string args;                                // out.txt is the results file
  int exit_code;
  std::string message;      // must appear in stderr
  int result_lines;         // lines expected in out.txt; -1: out.txt must not exist; kAsBefore:
                            // out.txt must hold what the setup wrote ("old results\n")
  Check check = nullptr;    // more to verify afterwards
  std::string prefix = "";  // shell code before the command
};

constexpr int kAsBefore = -2;

const std::string kTrack = "track seq --init init.txt -o out.txt -q ";
void no_setup(const fs::path&) {}

// Setups and checks for the output cases (issue 16).
void old_results(const fs::path& dir) { write_file(dir / "out.txt", "old results\n"); }

std::function<void(const fs::path&)> old_results_and(std::function<void(const fs::path&)> more) {
  return [more](const fs::path& dir) {
    old_results(dir);
    more(dir);
  };
}

void make_null_device(const fs::path& dir) {
  if (::mknod((dir / "null").c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0) {
    GTEST_SKIP() << "mknod is not permitted here";
  }
}

Check still_a_device(const std::string& name) {
  return [name](const fs::path& dir, const std::string&) {
    EXPECT_TRUE(fs::is_character_file(fs::symlink_status(dir / name)));
  };
}

Check file_unchanged(const std::string& name) {
  return [name](const fs::path& dir, const std::string&) {
    const std::string before = read_file(dir / (name + ".before"));
    EXPECT_FALSE(before.empty());
    EXPECT_EQ(read_file(dir / name), before) << name << " was changed";
  };
}

// Keeps a copy of `name` (made by the setup) to compare with after the run.
std::function<void(const fs::path&)> keep_copy(const std::string& name) {
  return [name](const fs::path& dir) { fs::copy_file(dir / name, dir / (name + ".before")); };
}

// The sequence as an MJPG video, dir/in.avi, with frame `dropped` (1-based) a dropped frame that
// the reader skips silently (0: none dropped).
std::function<void(const fs::path&)> sequence_video(int dropped) {
  return [dropped](const fs::path& dir) {
    if (dropped > 0) {
      ASSERT_EQ(
          write_avi_with_a_dropped_frame((dir / "in.avi").string(), sequence().frames, dropped),
          "");
      return;
    }
    cv::VideoWriter writer((dir / "in.avi").string(), cv::CAP_FFMPEG,
                           cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 10,
                           sequence().frames[0].size());
    for (const cv::Mat& frame : sequence().frames) writer.write(frame);
  };
}

std::vector<Case> make_cases() {
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
      // A vertex repeating the one before it (ground-truth files have them) is dropped, with a
      // note; a vertex repeated elsewhere cannot be a boundary's.
      {"polygon repeating a point", no_setup,
       inline_track + "'" + a + " " + b + " " + b + " " + c + "'", 0,
       "scbt: note: --init-points: 1 repeated vertex(es) dropped from the initial polygon", n},
      {"polygon file repeating its first point last",
       init_file(format_polygon_line(Polygon{t[0], t[1], t[2], t[3], t[0]}) + "\n"), kTrack, 0,
       "scbt: note: init.txt:1: 1 repeated vertex(es) dropped", n},
      {"polygon going back to a point", no_setup,
       inline_track + "'" + a + " " + b + " " + c + " " + b + "'", 2, "repeats a vertex", -1},
      {"self-intersecting polygon", no_setup, inline_track + "'10,10 100,10 10,90 60,100'", 2,
       "polygon crosses itself", -1},
      {"bowtie polygon", no_setup, inline_track + "'10,10 100,10 10,90 100,90'", 2,
       "polygon crosses itself", -1},
      {"zero-area polygon", no_setup, inline_track + "'10,10 20,20 30,30 40,40'", 2,
       "polygon encloses no area (its vertices lie on one line)", -1},
      {"polygon of half a pixel", no_setup, inline_track + "'10,10 11,10 10,11'", 2,
       "polygon encloses 0.5 px², smaller than 1 px²", -1},
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
       [](const fs::path& dir) {
         // Made when the case runs: the table is built in every test process.
         write_file(dir / "init.txt", "3 " + std::string(4 << 20, '7') + " 1 2 3 4 5\n");
       },
       kTrack, 1, "init.txt:1:", -1},
      {"missing polygon file", no_setup, "track seq --init none.txt -o out.txt", 1,
       "none.txt: cannot open for reading", -1},
      {"folder as polygon file",
       [](const fs::path& dir) { fs::create_directory(dir / "polygons"); },
       "track seq --init polygons -o out.txt", 1, "scbt: error: polygons: is a folder, not a file",
       -1},
      {"NUL byte in the polygon file", init_file(std::string("3 10 10 6\0 10 50 90\n", 20)), kTrack,
       1, "init.txt:1: coordinate '6\\x00' is not a number", -1},
      // --init-box: values as given, never wrapped; CSV-only runs.
      {"init box beyond 32 bits", no_setup,
       "track seq -o out.txt -q --init-box 4294967496,260,240,130", 2,
       "scbt: error: --init-box: x = 4294967496 is out of range", -1},
      {"init box width beyond 32 bits", no_setup,
       "track seq -o out.txt -q --init-box 0,0,99999999999,10", 2,
       "--init-box: w = 99999999999 is out of range", -1},
      {"init box with a fraction", no_setup, "track seq -o out.txt -q --init-box 1,2,3.5,4", 2,
       "--init-box must be four integers x,y,w,h (pixels), got '1,2,3.5,4'", -1},
      {"CSV-only run", no_setup, "track seq --init init.txt --csv stats.csv -q", 0, "", -1,
       [n](const fs::path& dir, const std::string&) {
         EXPECT_EQ(static_cast<int>(read_text_lines((dir / "stats.csv").string()).size()), n);
       }},
      {"no output at all", no_setup, "track seq --init init.txt -q", 2,
       "nothing to write: give -o/--output, --csv, --video, --frames-out or --points3d", -1},
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
      // Outputs that are not regular files are written in place, never replaced (issue 16).
      {"results to a device node", make_null_device, "track seq --init init.txt -o null -q", 0, "",
       -1, still_a_device("null")},
      {"results to a symlink to a device",
       [](const fs::path& dir) { fs::create_symlink("/dev/null", dir / "link"); },
       "track seq --init init.txt -o link -q", 0, "", -1,
       [](const fs::path& dir, const std::string&) {
         EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir / "link")));
         EXPECT_TRUE(fs::is_character_file("/dev/null"));
       }},
      {"results to a FIFO", [](const fs::path& dir) { ::mkfifo((dir / "fifo").c_str(), 0600); },
       "track seq --init init.txt -o fifo -q", 0, "", -1,
       [n](const fs::path& dir, const std::string&) {
         EXPECT_TRUE(fs::is_fifo(fs::symlink_status(dir / "fifo")));
         // The reader, started before the run, may still be writing its copy.
         for (int wait = 0; wait < 100; ++wait) {
           if (static_cast<int>(read_text_lines((dir / "copy.txt").string()).size()) == n) break;
           std::this_thread::sleep_for(std::chrono::milliseconds(50));
         }
         EXPECT_EQ(static_cast<int>(read_text_lines((dir / "copy.txt").string()).size()), n);
       },
       "(cat fifo > copy.txt &);"},
      {"results to a full device", no_setup, "track seq --init init.txt -o /dev/full -q", 1,
       "/dev/full: write failed: No space left on device", -1},
      {"results to a symlink to a regular file",
       [](const fs::path& dir) {
         fs::create_directory(dir / "real");
         write_file(dir / "real" / "results.txt", "old results\n");
         fs::create_symlink("real/results.txt", dir / "link");
       },
       "track seq --init init.txt -o link -q", 0, "", -1,
       [n](const fs::path& dir, const std::string&) {
         EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir / "link")));
         EXPECT_EQ(static_cast<int>(read_text_lines((dir / "link").string()).size()), n);
       }},
      {"an 0600 output stays 0600",
       [](const fs::path& dir) {
         old_results(dir);
         fs::permissions(dir / "out.txt", fs::perms::owner_read | fs::perms::owner_write);
       },
       kTrack, 0, "", n,
       [](const fs::path& dir, const std::string&) {
         EXPECT_EQ(fs::status(dir / "out.txt").permissions() & fs::perms::all,
                   fs::perms::owner_read | fs::perms::owner_write);
       }},
      // Outputs that would overwrite an input or each other are refused before tracking.
      {"results onto the init file", keep_copy("init.txt"), "track seq --init init.txt -o init.txt",
       2, "scbt: error: -o init.txt is the same file as --init init.txt", -1,
       file_unchanged("init.txt")},
      {"results onto an input image", keep_copy("seq/0001.png"),
       "track seq --init init.txt -o seq/0001.png", 2,
       "-o seq/0001.png is inside the input folder INPUT seq", -1, file_unchanged("seq/0001.png")},
      {"frames into the input folder", keep_copy("seq/0001.png"), kTrack + "--frames-out seq", 2,
       "--frames-out seq is the same folder as INPUT seq", -1, file_unchanged("seq/0001.png")},
      {"video onto the input video",
       [](const fs::path& dir) {
         sequence_video(0)(dir);
         keep_copy("in.avi")(dir);
       },
       "track in.avi --init init.txt -o out.txt --video in.avi", 2,
       "--video in.avi is the same file as INPUT in.avi", -1, file_unchanged("in.avi")},
      {"video and results onto one file", no_setup, kTrack + "--video out.txt", 2,
       "--video out.txt is the same file as -o out.txt", -1},
      {"csv and results onto one file", old_results, kTrack + "--csv out.txt", 2,
       "--csv out.txt is the same file as -o out.txt", kAsBefore},
      {"csv and results both to stdout", no_setup, "track seq --init init.txt -o - --csv -", 2,
       "--csv - is the same file as -o -", -1},
      // A failed run replaces nothing and leaves no temporary file.
      {"csv naming a folder",
       old_results_and([](const fs::path& dir) { fs::create_directory(dir / "stats"); }),
       kTrack + "--csv stats", 1, "stats: is a folder, not a file", kAsBefore},
      {"results naming a folder",
       [](const fs::path& dir) { fs::create_directory(dir / "results"); },
       "track seq --init init.txt -o results", 1, "results: is a folder, not a file", -1},
      {"video naming a folder",
       old_results_and([](const fs::path& dir) { fs::create_directory(dir / "video.avi"); }),
       kTrack + "--video video.avi", 1, "video.avi: is a folder, not a file", kAsBefore},
      {"video named like an image pattern", old_results, kTrack + "--video 'f%02d.jpg'", 2,
       "must end in .avi, .mkv, .mp4 or .m4v", kAsBefore,
       [](const fs::path& dir, const std::string&) {
         EXPECT_FALSE(fs::exists(dir / "f00.jpg"));
         EXPECT_FALSE(fs::exists(dir / "f01.jpg"));
       }},
      {"video on a full disk", old_results, kTrack + "--video big.avi", 1,
       "big.avi: write failed: the finished video", kAsBefore,
       [](const fs::path& dir, const std::string&) { EXPECT_FALSE(fs::exists(dir / "big.avi")); },
       // Files may grow to 6 KiB only (ulimit counts 512-byte blocks): the results can, the
       // video (5.5 KiB of AVI header, then the frames) cannot.
       "trap '' XFSZ; ulimit -f 12;"},
      {"annotated frames on a full disk", no_setup,
       "track seq --init init.txt -o /dev/null -q --frames-out frames", 1,
       "frames/0001.jpg: write failed: File too large", -1,
       [](const fs::path& dir, const std::string&) {
         EXPECT_TRUE(!fs::exists(dir / "frames") || fs::is_empty(dir / "frames"))
             << "a partial frame left behind";
       },
       // 1 KiB per file: less than any annotated frame.
       "trap '' XFSZ; ulimit -f 2;"},
      // Bounded reads.
      {"init file that never ends", no_setup, "track seq --init /dev/zero -o out.txt", 1,
       "/dev/zero:1: line longer than 1 MiB", -1},
      {"init polygon over the vertex limit",
       [](const fs::path& dir) {
         // Large enough for neighbours to stay apart at two decimals: a repeated vertex would be
         // dropped.
         Polygon circle;
         for (int i = 0; i <= kMaxBoundaryVertices; ++i) {
           const double angle = 2.0 * M_PI * i / (kMaxBoundaryVertices + 1);
           circle.emplace_back(80 + 55 * std::cos(angle), 60 + 55 * std::sin(angle));
         }
         write_file(dir / "init.txt", format_polygon_line(circle) + "\n");
       },
       kTrack, 1, "at most 20000", -1},
      {"polygon file with a byte-order mark",
       init_file("\xEF\xBB\xBF" + format_polygon_line(t) + "\n"), kTrack, 1,
       "init.txt:1: line starts with a UTF-8 byte-order mark", -1},
      {"denormal coordinate is a number", init_file("4 1e-310 1e-310 60 0 60 40 0 40\n"), kTrack, 0,
       "", n},
      // Frames that would silently shift every later one.
      {"first image name is a folder",
       [](const fs::path& dir) {
         fs::remove(dir / "seq" / frame_name(1));
         fs::create_directory(dir / "seq" / frame_name(1));
       },
       kTrack, 1, "seq/0001.png: named like a frame but not a regular file", -1},
      {"numbering starting at 0005",
       [](const fs::path& dir) {
         for (int i = 1; i <= 4; ++i) fs::remove(dir / "seq" / frame_name(i));
       },
       kTrack, 1, "seq: image numbering starts at 0005.png, not at 0 or 1", -1},
      {"video frame the reader skips: held in place", sequence_video(5),
       "track in.avi --init init.txt -o out.txt -q --csv out.csv", 3,
       "scbt: warning: in.avi frame 5: skipped by the video decoder", n,
       [](const fs::path& dir, const std::string&) {
         const std::vector<std::string> rows = read_text_lines((dir / "out.csv").string());
         ASSERT_GE(rows.size(), 5u);
         EXPECT_EQ(rows[4].rfind("5,1,", 0), 0u) << rows[4];  // frame 5 held, in its place
       }},
      {"newline in a folder name cannot forge a line",
       [](const fs::path& dir) {
         fs::rename(dir / "seq", dir / "x\nscbt: error: forged");
         write_file(dir / "x\nscbt: error: forged" / frame_name(4), "garbage");
       },
       "track \"$(printf 'x\\nscbt: error: forged')\" --init init.txt -o out.txt -q", 3,
       "x\\nscbt: error: forged/0004.png: cannot decode image", n,
       [](const fs::path&, const std::string& err) {
         EXPECT_EQ(err.find("\nscbt: error: forged"), std::string::npos) << err;
       }},
  };
}

// Built once per process: gtest asks for it for every case's name.
const std::vector<Case>& cases() {
  static const std::vector<Case> all = make_cases();
  return all;
}

class CliBadInputTest : public ::testing::TestWithParam<size_t> {};

TEST_P(CliBadInputTest, MessageExitCodeAndOutput) {
  const Case& c = cases()[GetParam()];
  SCOPED_TRACE(c.name);
  const fs::path dir =
      fs::temp_directory_path() /
      ("scbt_cli_bad_input_" + std::to_string(::getpid()) + "_" + std::to_string(GetParam()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  write_sequence(dir);
  c.setup(dir);
  if (::testing::Test::IsSkipped()) {
    fs::remove_all(dir);
    return;
  }
  const RunResult r = run_scbt(dir, c.args, c.prefix);
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
  if (c.result_lines == kAsBefore) {
    EXPECT_EQ(read_file(dir / "out.txt"), "old results\n");
  } else if (c.result_lines < 0) {
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
  if (c.check) c.check(dir, r.err);
  // No temporary file is left behind, anywhere.
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(dir)) {
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
    dir_ = fresh_test_dir("scbt_cli_run");
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

// A long input: the first frame repeated (copies are cheap; decoding and tracking are not).
void lengthen_sequence(const fs::path& dir, int frames) {
  for (int i = static_cast<int>(sequence().frames.size()) + 1; i <= frames; ++i) {
    fs::copy_file(dir / "seq" / frame_name(1), dir / "seq" / frame_name(i));
  }
}

// Waits until the run has opened its outputs (its temporary files exist), which it does after
// installing its signal handlers: a signal sent earlier would find the default action.
void wait_until_tracking(const fs::path& dir) {
  for (int wait = 0; wait < 600; ++wait) {
    for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
      if (e.path().filename().string().find(".tmp-") != std::string::npos) {
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        return;
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ADD_FAILURE() << "the run did not open its outputs within 30 s";
}

void expect_no_temporary_files(const fs::path& dir) {
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(dir)) {
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
  }
}

// SIGTERM / SIGINT / SIGHUP mid-run: the frames tracked so far form a complete results file, the
// run says how far it got, and the exit code is 128 + the signal.
void expect_interrupted_cleanly(const fs::path& dir, int signal_number) {
  const int frames = 4000;
  lengthen_sequence(dir, frames);
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
  wait_until_tracking(dir);
  ::kill(child, signal_number);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
  const std::string err = read_file(dir / "stderr.txt");
  ASSERT_EQ(WEXITSTATUS(status), 128 + signal_number) << err;
  const std::string name = signal_number == SIGINT   ? "SIGINT"
                           : signal_number == SIGHUP ? "SIGHUP"
                                                     : "SIGTERM";
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
  expect_no_temporary_files(dir);
}

TEST_F(CliRunTest, SigtermFlushesAValidResultsFile) { expect_interrupted_cleanly(dir_, SIGTERM); }

TEST_F(CliRunTest, SigintFlushesAValidResultsFile) { expect_interrupted_cleanly(dir_, SIGINT); }

// A closed terminal ends the run like SIGTERM (exit code 129).
TEST_F(CliRunTest, SighupFlushesAValidResultsFile) { expect_interrupted_cleanly(dir_, SIGHUP); }

// `scbt track -o - | head -n 2`: the results stream out line by line while tracking goes on; when
// the reader leaves, the run ends cleanly (exit code 141) with the CSV complete up to that frame.
TEST_F(CliRunTest, StdoutStreamsLiveAndAClosedPipeEndsTheRunCleanly) {
  const int frames = 4000;
  lengthen_sequence(dir_, frames);
  int pipe_ends[2];
  ASSERT_EQ(::pipe(pipe_ends), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const std::string err = (dir_ / "stderr.txt").string();
    if (!std::freopen(err.c_str(), "w", stderr)) ::_exit(127);
    if (::chdir(dir_.c_str()) != 0) ::_exit(127);
    ::dup2(pipe_ends[1], STDOUT_FILENO);
    ::close(pipe_ends[0]);
    ::close(pipe_ends[1]);
    ::execl(SCBT_BINARY, SCBT_BINARY, "track", "seq", "--init", "init.txt", "-o", "-", "-q",
            "--csv", "out.csv", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(pipe_ends[1]);
  std::string received;
  char c = 0;
  while (std::count(received.begin(), received.end(), '\n') < 2 &&
         ::read(pipe_ends[0], &c, 1) == 1) {
    received += c;
  }
  int status = 0;
  EXPECT_EQ(::waitpid(child, &status, WNOHANG), 0) << "the lines came only at the end of the run";
  ::close(pipe_ends[0]);  // the reader leaves
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
  const std::string err = read_file(dir_ / "stderr.txt");
  EXPECT_EQ(WEXITSTATUS(status), 141) << err;
  const std::vector<std::string> lines = read_text_lines_of(received);
  ASSERT_EQ(lines.size(), 2u);
  for (const std::string& line : lines) {
    Polygon polygon;
    std::string error;
    EXPECT_TRUE(try_parse_polygon_line(line, &polygon, &error)) << line << ": " << error;
  }
  const std::string needle = "went away (EPIPE) after frame ";
  const size_t at = err.find(needle);
  ASSERT_NE(at, std::string::npos) << err;
  const int reached = std::atoi(err.c_str() + at + needle.size());
  EXPECT_GE(reached, 2);
  EXPECT_LT(reached, frames);
  EXPECT_EQ(static_cast<int>(read_text_lines((dir_ / "out.csv").string()).size()), reached);
  expect_no_temporary_files(dir_);
}

// Runs `command` (shell code, in dir) and returns its exit code.
int run_shell(const fs::path& dir, const std::string& command) {
  const int status = std::system(("cd '" + dir.string() + "' && " + command).c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1000 + WTERMSIG(status);
}

void expect_only_polygon_lines(const fs::path& path, int count) {
  const std::vector<std::string> lines = read_text_lines(path.string());
  EXPECT_EQ(static_cast<int>(lines.size()), count) << path;
  for (const std::string& line : lines) {
    Polygon polygon;
    std::string error;
    EXPECT_TRUE(try_parse_polygon_line(line, &polygon, &error)) << line << ": " << error;
  }
}

// Closed standard descriptors are not taken over by outputs: the progress bar never lands in the
// results, streamed results never in the CSV.
TEST_F(CliRunTest, ClosedStandardDescriptorsAreNotTakenOverByOutputs) {
  const int n = static_cast<int>(sequence().frames.size());
  const std::string scbt = std::string("'") + SCBT_BINARY + "' ";
  EXPECT_EQ(run_shell(dir_, scbt + "track seq --init init.txt -o out.txt 2>&-"), 0);
  expect_only_polygon_lines(dir_ / "out.txt", n);
  EXPECT_EQ(run_shell(dir_, scbt + "track seq --init init.txt -o - --csv out.csv -q >&-"), 0);
  const std::vector<std::string> rows = read_text_lines((dir_ / "out.csv").string());
  ASSERT_EQ(static_cast<int>(rows.size()), n);
  for (size_t i = 1; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].rfind(std::to_string(i + 1) + ",", 0), 0u) << rows[i];
  }
  EXPECT_EQ(run_shell(dir_, scbt + "track seq --init init.txt -o out.txt -q <&- >&- 2>&-"), 0);
  expect_only_polygon_lines(dir_ / "out.txt", n);
}

// Whether `pid` catches `signal_number` (its handler is installed): /proc/PID/status, SigCgt.
bool catches(pid_t pid, int signal_number) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(status, line);) {
    if (line.rfind("SigCgt:", 0) == 0) {
      const unsigned long long mask = std::stoull(line.substr(7), nullptr, 16);
      return (mask >> (signal_number - 1)) & 1u;
    }
  }
  return false;
}

// Starts scbt with `args` in dir (stderr to dir/stderr.txt), `prefix` shell code first.
pid_t start_scbt(const fs::path& dir, const std::string& args, const std::string& prefix = "") {
  const pid_t child = ::fork();
  if (child == 0) {
    const std::string command =
        prefix + " exec '" + std::string(SCBT_BINARY) + "' " + args + " 2> stderr.txt > /dev/null";
    if (::chdir(dir.c_str()) != 0) ::_exit(127);
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  return child;
}

int wait_exit_code(pid_t child) {
  int status = 0;
  if (::waitpid(child, &status, 0) != child) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1000 + WTERMSIG(status);
}

// A run waiting on a FIFO (an output without a reader, a camera info without a writer) ends on
// SIGTERM with 143, naming what it waited for, not with "Interrupted system call".
void expect_sigterm_ends_a_wait(const fs::path& dir, const std::string& args,
                                const std::string& message) {
  ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0600), 0);
  const pid_t child = start_scbt(dir, args);
  ASSERT_GT(child, 0);
  for (int wait = 0; wait < 600 && !catches(child, SIGTERM); ++wait) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // into the wait
  ::kill(child, SIGTERM);
  const int code = wait_exit_code(child);
  const std::string err = read_file(dir / "stderr.txt");
  EXPECT_EQ(code, 143) << err;
  EXPECT_NE(err.find(message), std::string::npos) << err;
  EXPECT_EQ(err.find("Interrupted system call"), std::string::npos) << err;
  expect_no_temporary_files(dir);
}

TEST_F(CliRunTest, SigtermWhileAnOutputFifoWaitsForItsReader) {
  expect_sigterm_ends_a_wait(dir_, "track seq --init init.txt -o fifo -q",
                             "scbt: error: fifo: waiting for a reader: interrupted by SIGTERM");
}

TEST_F(CliRunTest, SigtermWhileACameraInfoFifoWaitsForItsWriter) {
  expect_sigterm_ends_a_wait(
      dir_,
      "track seq --init init.txt -o out.txt -q --depth seq --camera-info fifo --points3d p.csv",
      "scbt: error: fifo: interrupted by SIGTERM");
  EXPECT_FALSE(fs::exists(dir_ / "out.txt"));
}

// An inherited SIG_IGN stays (nohup, a script's background job): SIGHUP and SIGINT do not end
// the run; SIGTERM still does.
TEST_F(CliRunTest, IgnoredHangupAndInterruptStayIgnored) {
  lengthen_sequence(dir_, 4000);
  const pid_t child =
      start_scbt(dir_, "track seq --init init.txt -o out.txt -q --csv out.csv", "trap '' HUP INT;");
  ASSERT_GT(child, 0);
  wait_until_tracking(dir_);
  EXPECT_FALSE(catches(child, SIGHUP));
  EXPECT_FALSE(catches(child, SIGINT));
  ::kill(child, SIGHUP);
  ::kill(child, SIGINT);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  int status = 0;
  EXPECT_EQ(::waitpid(child, &status, WNOHANG), 0) << "the run ended on an ignored signal";
  ::kill(child, SIGTERM);
  EXPECT_EQ(wait_exit_code(child), 143) << read_file(dir_ / "stderr.txt");
  EXPECT_NE(read_file(dir_ / "stderr.txt").find("interrupted by SIGTERM"), std::string::npos);
}

// --start-frame N with a file of one polygon per frame (a ground-truth file): line N is the
// boundary on frame N. With any other number of lines, line 1, and a warning says so.
TEST_F(CliRunTest, StartFrameTakesItsLineOfAPolygonPerFrameFile) {
  const int n = static_cast<int>(sequence().frames.size());
  // One polygon per frame, each its own (a box shifted by its frame number).
  std::string truth;
  for (int k = 1; k <= n; ++k) {
    const double x = 20 + k, y = 30;
    truth +=
        format_polygon_line(Polygon{{x, y}, {x + 40, y}, {x + 40, y + 30}, {x, y + 30}}) + "\n";
  }
  write_file(dir_ / "truth.txt", truth + "\n");  // a trailing blank line is not a frame
  RunResult r = run_scbt(dir_, "track seq --init truth.txt -o out.txt -q --start-frame 5");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  std::vector<std::string> lines = read_text_lines((dir_ / "out.txt").string());
  ASSERT_EQ(static_cast<int>(lines.size()), n - 4);
  EXPECT_EQ(lines[0], read_text_lines((dir_ / "truth.txt").string())[4]);
  // Beyond the input (and the file): the start frame is refused, no line is taken.
  r = run_scbt(dir_, "track seq --init truth.txt -o out.txt -q --start-frame 20");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--start-frame 20 is beyond the input"), std::string::npos) << r.err;

  // Two lines for eight frames: not one per frame.
  write_file(dir_ / "two.txt", read_text_lines((dir_ / "truth.txt").string())[0] + "\n" +
                                   read_text_lines((dir_ / "truth.txt").string())[1] + "\n");
  r = run_scbt(dir_, "track seq --init two.txt -o out.txt -q --start-frame 5");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("scbt: warning: two.txt has 2 lines, not one per frame of seq (" +
                       std::to_string(n) + " frames): its first line is the boundary on frame 5"),
            std::string::npos)
      << r.err;
  lines = read_text_lines((dir_ / "out.txt").string());
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines[0], read_text_lines((dir_ / "truth.txt").string())[0]);
}

// Progress counts the frames that will run; written to a file (no terminal), it is plain lines
// without carriage returns.
TEST_F(CliRunTest, ProgressCountsTheFramesThatRunAndWritesPlainLinesToAFile) {
  const RunResult r = run_scbt(dir_, "track seq --init init.txt -o out.txt --max-frames 5");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find('\r'), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("tracking: 5/5 frames (100%)"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("/8"), std::string::npos) << r.err;
  EXPECT_EQ(static_cast<int>(read_text_lines((dir_ / "out.txt").string()).size()), 5);
}

}  // namespace
}  // namespace scbt
