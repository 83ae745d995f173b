// `scbt track` end to end on rendered scenes: the state and confidence columns, the results file
// while the object is lost, the annotated frames coloured by state, --start-frame and --init-box.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "cli_test_util.h"
#include "scbt/geometry/polygon_io.h"
#include "scbt/synthetic/gap_scene.h"

namespace scbt {
namespace {

namespace fs = std::filesystem;
using cli_test::fresh_test_dir;
using cli_test::read_file;
using cli_test::read_text_lines_of;
using cli_test::run_scbt;

std::string frame_name(int index) {
  char name[16];
  std::snprintf(name, sizeof(name), "%04d.png", index);
  return name;
}

// Splits one CSV line at commas (the fields tested here are never quoted).
std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  for (char c : line) {
    if (c == ',') {
      fields.push_back(field);
      field.clear();
    } else {
      field += c;
    }
  }
  fields.push_back(field);
  return fields;
}

// A rendered scene whose frames 1.. are blank (uniform grey) for a while: written as
// dir/seq/0001.png ..., with the truth of every frame kept.
class CliTrackTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fresh_test_dir("scbt_cli_track");
    fs::create_directories(dir_ / "seq");
    SceneOptions scene;
    scene.size = cv::Size(240, 180);
    scene.object_size = 40.0;
    scene.clutter_strokes = 10;
    scene.shape = SceneShape::kBox;
    GapSceneOptions gap;
    gap.kind = GapKind::kBlank;
    gap.frames_before = 8;
    gap.gap = 8;
    gap.frames_after = 10;
    gap.drift = 0.5;
    scene_ = render_gap_scene(scene, gap);
    for (size_t k = 0; k < scene_.frames.size(); ++k) {
      ASSERT_TRUE(cv::imwrite((dir_ / "seq" / frame_name(static_cast<int>(k) + 1)).string(),
                              scene_.frames[k].image));
    }
  }
  void TearDown() override { fs::remove_all(dir_); }

  // The truth of frame `number` (1-based) as "x,y x,y ...".
  std::string truth_points(int number) const {
    std::string text;
    for (const Point& p : scene_.frames[number - 1].truth) {
      text += (text.empty() ? "" : " ") + std::to_string(p.x) + "," + std::to_string(p.y);
    }
    return text;
  }
  Polygon result_line(int line) const {
    const std::vector<std::string> lines = read_text_lines_of(read_file(dir_ / "out.txt"));
    Polygon polygon;
    std::string error;
    EXPECT_TRUE(try_parse_polygon_line(lines.at(line), &polygon, &error)) << error;
    return polygon;
  }

  fs::path dir_;
  GapScene scene_;
};

// Pixels of an annotated frame near a colour (BGR; JPEG moves colours a little).
int pixels_near(const cv::Mat& image, const cv::Vec3b& color) {
  int n = 0;
  for (int y = 0; y < image.rows; ++y) {
    for (int x = 0; x < image.cols; ++x) {
      const cv::Vec3b p = image.at<cv::Vec3b>(y, x);
      n += std::abs(p[0] - color[0]) < 60 && std::abs(p[1] - color[1]) < 60 &&
                   std::abs(p[2] - color[2]) < 60
               ? 1
               : 0;
    }
  }
  return n;
}

TEST_F(CliTrackTest, LostFramesKeepALineAndSayLostInTheCsvAndTheVideo) {
  const int n = static_cast<int>(scene_.frames.size());
  const auto r = run_scbt(dir_, "track seq --init-points '" + truth_points(1) +
                                    "' -o out.txt --csv out.csv --frames-out ann -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> results = read_text_lines_of(read_file(dir_ / "out.txt"));
  ASSERT_EQ(static_cast<int>(results.size()), n);  // one line per frame, lost ones included
  const std::vector<std::string> csv = read_text_lines_of(read_file(dir_ / "out.csv"));
  ASSERT_EQ(static_cast<int>(csv.size()), n);  // header + every frame but the initial one
  const std::vector<std::string> header = fields_of(csv[0]);
  ASSERT_GE(header.size(), 4u);
  EXPECT_EQ(header[2], "state");
  EXPECT_EQ(header[3], "confidence");

  int first_hidden = 0, first_lost = 0, tracking_after = 0;
  for (int k = 1; k < n; ++k) {  // CSV row k is frame k + 1 (0-based frame k)
    const std::vector<std::string> row = fields_of(csv[k]);
    ASSERT_EQ(std::stoi(row[0]), k + 1);
    const std::string& state = row[2];
    const double confidence = std::stod(row[3]);
    EXPECT_TRUE(state == "tracking" || state == "uncertain" || state == "lost") << state;
    EXPECT_GE(confidence, 0.0);
    EXPECT_LE(confidence, 1.0);
    if (scene_.hidden[k] && first_hidden == 0) first_hidden = k;
    if (scene_.hidden[k]) {
      EXPECT_NE(state, "tracking") << "frame " << k + 1;
    }
    if (state == "lost") {
      if (first_lost == 0) first_lost = k;
      EXPECT_EQ(confidence, 0.0);
      EXPECT_EQ(row[1], "1");  // held: the last confident boundary repeated
      EXPECT_NE(csv[k].find("lost"), std::string::npos);
      // The repeated boundary is the one of the previous lost frame.
      if (fields_of(csv[k - 1])[2] == "lost") {
        EXPECT_EQ(results[k], results[k - 1]);
      }
    }
    if (k >= scene_.first_back && state == "tracking") ++tracking_after;
    // The note names the search step that found the boundary (none when held or lost).
    if (row[1] == "0" && state != "lost") {
      EXPECT_NE(csv[k].find("step: "), std::string::npos) << csv[k];
    } else {
      EXPECT_EQ(csv[k].find("step: "), std::string::npos) << csv[k];
    }
  }
  ASSERT_GT(first_hidden, 0);
  ASSERT_GT(first_lost, 0) << "never lost";
  EXPECT_LE(first_lost, first_hidden + 3);
  EXPECT_GE(tracking_after, n - scene_.first_back - 5) << "not found again after the gap";

  // The annotated frames: green boundary while tracking, red (and no green) while lost.
  const cv::Vec3b green(0, 220, 0), red(0, 0, 255);
  const cv::Mat tracked = cv::imread((dir_ / "ann" / "0003.jpg").string());
  ASSERT_FALSE(tracked.empty());
  EXPECT_GT(pixels_near(tracked, green), 50);
  char lost_name[16];
  std::snprintf(lost_name, sizeof(lost_name), "%04d.jpg", first_lost + 1);
  const cv::Mat lost_image = cv::imread((dir_ / "ann" / lost_name).string());
  ASSERT_FALSE(lost_image.empty()) << lost_name;
  EXPECT_LT(pixels_near(lost_image, green), 5);
  EXPECT_GT(pixels_near(lost_image, red), 50);
}

TEST_F(CliTrackTest, StartFrameIsOneBasedAndTheResultsStartThere) {
  const int n = static_cast<int>(scene_.frames.size());
  const auto r = run_scbt(dir_, "track seq --start-frame 3 --init-points '" + truth_points(3) +
                                    "' -o out.txt --csv out.csv -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> results = read_text_lines_of(read_file(dir_ / "out.txt"));
  EXPECT_EQ(static_cast<int>(results.size()), n - 2);
  const std::vector<std::string> csv = read_text_lines_of(read_file(dir_ / "out.csv"));
  ASSERT_GE(csv.size(), 2u);
  EXPECT_EQ(fields_of(csv[1])[0], "4");  // the row after the initial frame 3
  // The second line is frame 4, tracked from frame 3's truth.
  EXPECT_LT(mean_boundary_distance(result_line(1), scene_.frames[3].truth), 2.0);

  const auto last = run_scbt(dir_, "track seq --start-frame " + std::to_string(n) +
                                       " --init-points '" + truth_points(n) + "' -o last.txt -q");
  EXPECT_EQ(last.exit_code, 0) << last.err;
  EXPECT_EQ(read_text_lines_of(read_file(dir_ / "last.txt")).size(), 1u);
}

TEST_F(CliTrackTest, StartFrameBeyondTheInputOrBelowOneIsAnError) {
  const int n = static_cast<int>(scene_.frames.size());
  const auto beyond = run_scbt(dir_, "track seq --start-frame " + std::to_string(n + 1) +
                                         " --init-points '" + truth_points(1) + "' -o out.txt -q");
  EXPECT_EQ(beyond.exit_code, 2);
  EXPECT_NE(beyond.err.find("--start-frame " + std::to_string(n + 1) + " is beyond the input"),
            std::string::npos)
      << beyond.err;
  EXPECT_NE(beyond.err.find("has " + std::to_string(n) + " frame"), std::string::npos)
      << beyond.err;
  const auto zero = run_scbt(
      dir_, "track seq --start-frame 0 --init-points '" + truth_points(1) + "' -o out.txt -q");
  EXPECT_EQ(zero.exit_code, 2);
  EXPECT_NE(zero.err.find("1-based"), std::string::npos) << zero.err;
  EXPECT_FALSE(fs::exists(dir_ / "out.txt"));
}

TEST_F(CliTrackTest, InitBoxFindsTheObjectInsideTheBox) {
  double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9;
  for (const Point& p : scene_.frames[0].truth) {
    x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
  }
  const cv::Rect truth_box(cvFloor(x0), cvFloor(y0), cvCeil(x1 - x0), cvCeil(y1 - y0));
  const int margin = truth_box.width * 15 / 100;
  const cv::Rect box(truth_box.x - margin, truth_box.y - margin, truth_box.width + 2 * margin,
                     truth_box.height + 2 * margin);
  const std::string spec = std::to_string(box.x) + "," + std::to_string(box.y) + "," +
                           std::to_string(box.width) + "," + std::to_string(box.height);
  const auto r = run_scbt(dir_, "track seq --init-box " + spec + " -o out.txt --max-frames 4 -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_LT(mean_boundary_distance(result_line(0), scene_.frames[0].truth), 1.5);
  EXPECT_LT(mean_boundary_distance(result_line(3), scene_.frames[3].truth), 2.0);
}

TEST_F(CliTrackTest, BadInitBoxesAreNamedErrors) {
  struct BadBox {
    std::string args;
    int exit_code;
    std::string message;
  };
  const std::vector<BadBox> cases = {
      {"--init-box 200,150,100,100", 2, "inside the 240x180 frame"},  // leaves the frame
      {"--init-box 10,10,0,20", 2, "is empty"},
      {"--init-box 10,10,20", 2, "four integers"},
      {"--init-box 1,1,30,30 --init-points '1,1 9,1 9,9'", 2, "cannot be combined"},
      {"--init-box 1,1,2,2", 2, "at least 8x8"},
  };
  for (const BadBox& c : cases) {
    const auto r = run_scbt(dir_, "track seq " + c.args + " -o out.txt -q");
    EXPECT_EQ(r.exit_code, c.exit_code) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "out.txt")) << c.args;
  }
  // A box over flat image holds no closed boundary: bad input data (exit 1), named.
  fs::create_directories(dir_ / "flat");
  ASSERT_TRUE(cv::imwrite((dir_ / "flat" / "0001.png").string(),
                          cv::Mat(180, 240, CV_8UC3, cv::Scalar::all(128))));
  const auto flat = run_scbt(dir_, "track flat --init-box 40,40,100,100 -o out.txt -q");
  EXPECT_EQ(flat.exit_code, 1) << flat.err;
  EXPECT_NE(flat.err.find("no closed boundary"), std::string::npos) << flat.err;
  EXPECT_FALSE(fs::exists(dir_ / "out.txt"));
}

}  // namespace
}  // namespace scbt
