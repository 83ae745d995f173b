#include "scbt/app/demo_run.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <opencv2/videoio.hpp>
#include <sstream>
#include <stdexcept>

#include "scbt/geometry/polygon_io.h"

namespace scbt {
namespace {
namespace fs = std::filesystem;

// A fresh folder per test, removed afterwards.
class DemoRunTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("scbt-demo-test-" + std::to_string(::getpid()) + "-" + info->name());
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

std::vector<Polygon> read_polygons(const std::string& path) {
  std::vector<Polygon> polygons;
  for (const std::string& line : read_text_lines(path)) {
    if (!line.empty()) polygons.push_back(parse_polygon_line(line));
  }
  return polygons;
}

TEST_F(DemoRunTest, ShortClipOfEachShapeIsTrackedAndWritten) {
  const SceneShape shapes[] = {SceneShape::kRim, SceneShape::kBox, SceneShape::kPolygon};
  for (SceneShape shape : shapes) {
    DemoOptions options;
    options.out_dir = (dir_ / to_string(shape)).string();
    options.frames = 30;
    options.quiet = true;
    options.scene.shape = shape;
    options.scene.seed = 3;
    options.video = shape == SceneShape::kRim;  // one video is enough to check the writer
    std::ostringstream log;
    const DemoSummary summary = run_demo(options, log);
    EXPECT_TRUE(log.str().empty()) << "quiet run logged: " << log.str();

    EXPECT_EQ(summary.frames, 30);
    EXPECT_EQ(summary.tracked, 29);
    ASSERT_EQ(summary.errors.size(), 29u);
    EXPECT_LT(summary.mean_error, 1.5) << to_string(shape);
    EXPECT_LE(summary.mean_error, summary.max_error);
    EXPECT_GE(summary.share_under_2px, 0.9) << to_string(shape);
    EXPECT_GT(summary.fps, 0.0);

    // results.txt and truth.txt: one polygon line per frame, frame 1 being the initial outline.
    const std::vector<Polygon> results = read_polygons(summary.results_path);
    const std::vector<Polygon> truth = read_polygons(summary.truth_path);
    ASSERT_EQ(results.size(), 30u);
    ASSERT_EQ(truth.size(), 30u);
    EXPECT_EQ(format_polygon_line(results[0]), format_polygon_line(truth[0]));
    // The summary's errors are those of the written polygons (up to their two decimals).
    double sum = 0.0;
    for (size_t k = 1; k < results.size(); ++k) {
      const double error = mean_boundary_distance(results[k], truth[k], 0.5);
      EXPECT_NEAR(error, summary.errors[k - 1], 0.02) << "frame " << k + 1;
      sum += error;
    }
    EXPECT_NEAR(sum / 29.0, summary.mean_error, 0.02);
    EXPECT_EQ(read_text_lines(summary.errors_path).size(), 31u);  // header + one row per frame

    if (options.video) {
      ASSERT_TRUE(fs::exists(summary.video_path));
      cv::VideoCapture capture(summary.video_path);
      ASSERT_TRUE(capture.isOpened());
      int decoded = 0;
      cv::Mat image;
      while (capture.read(image)) {
        EXPECT_EQ(image.size(), options.scene.size);
        ++decoded;
      }
      EXPECT_EQ(decoded, 30);
    } else {
      EXPECT_TRUE(summary.video_path.empty());
      EXPECT_FALSE(fs::exists(fs::path(options.out_dir) / "demo.avi"));
    }
    // Nothing temporary left behind.
    for (const auto& entry : fs::directory_iterator(options.out_dir)) {
      EXPECT_EQ(entry.path().filename().string().find("tmp"), std::string::npos) << entry.path();
    }
  }
}

TEST_F(DemoRunTest, SameOptionsGiveIdenticalResults) {
  DemoOptions options;
  options.frames = 12;
  options.quiet = true;
  options.video = false;
  options.scene.seed = 11;
  std::ostringstream log;
  options.out_dir = (dir_ / "a").string();
  const DemoSummary a = run_demo(options, log);
  options.out_dir = (dir_ / "b").string();
  const DemoSummary b = run_demo(options, log);
  EXPECT_EQ(read_text_lines(a.results_path), read_text_lines(b.results_path));
  EXPECT_EQ(read_text_lines(a.truth_path), read_text_lines(b.truth_path));
  EXPECT_EQ(a.errors, b.errors);
}

TEST_F(DemoRunTest, BadOptionsAreRejectedWithoutWritingFiles) {
  std::ostringstream log;
  DemoOptions options;
  options.out_dir = dir_.string();
  options.quiet = true;
  options.frames = 1;
  EXPECT_THROW(run_demo(options, log), std::invalid_argument);
  options.frames = 10;
  options.out_dir = "";
  EXPECT_THROW(run_demo(options, log), std::invalid_argument);
  options.out_dir = dir_.string();
  options.motion.amplitude = {1000.0, 0.0};  // leaves the frame
  try {
    run_demo(options, log);
    ADD_FAILURE() << "a path leaving the frame was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("leaves"), std::string::npos) << e.what();
  }
  options.motion = MotionOptions();
  options.tracker.filter_distance = -1.0;
  EXPECT_THROW(run_demo(options, log), std::invalid_argument);
  EXPECT_FALSE(fs::exists(dir_ / "results.txt"));
  EXPECT_FALSE(fs::exists(dir_ / "truth.txt"));
}

TEST(DemoSummaryTest, FormatNamesTheFigures) {
  DemoSummary s;
  s.frames = 10;
  s.tracked = 9;
  s.held = 2;
  s.mean_error = 0.75;
  s.max_error = 3.25;
  s.worst_frame = 7;
  s.share_under_2px = 0.5;
  s.video_path = "x/demo.avi";
  const std::string text = format_demo_summary(s);
  EXPECT_NE(text.find("held 2"), std::string::npos) << text;
  EXPECT_NE(text.find("mean 0.75 px"), std::string::npos) << text;
  EXPECT_NE(text.find("max 3.25 px (frame 7)"), std::string::npos) << text;
  EXPECT_NE(text.find("50.0%"), std::string::npos) << text;
  EXPECT_NE(text.find("x/demo.avi"), std::string::npos) << text;
}

}  // namespace
}  // namespace scbt
