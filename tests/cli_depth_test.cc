// `scbt track --depth` end to end: a rendered RGB-D clip of a bowl (colour frames, 16-bit depth
// PNGs with the sensor's artefacts, a TUM RGB-D copy of it, a ROS camera_info file) is written to
// a temporary folder, the built binary tracks it, and the CSV's centroids and normals are
// compared with the scene's truth. Bad depth inputs must fail with one clear error line.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cli_test_util.h"
#include "scbt/geometry/polygon_io.h"
#include "scbt/synthetic/rgbd_scene.h"
#include "scbt/synthetic/rgbd_sensor.h"

namespace scbt {
namespace {

namespace fs = std::filesystem;

// Its folder is removed with it (the process id in its name leaves nothing shared to clean).
struct Clip {
  fs::path dir;
  std::vector<Eigen::Vector3d> centres, normals;

  Clip() = default;
  Clip(Clip&& other) noexcept
      : dir(std::exchange(other.dir, {})),
        centres(std::move(other.centres)),
        normals(std::move(other.normals)) {}
  ~Clip() {
    std::error_code ignored;
    if (!dir.empty()) fs::remove_all(dir, ignored);
  }
};

std::string number_name(int i) {
  char name[16];
  std::snprintf(name, sizeof name, "%04d.png", i);
  return name;
}

// 12 frames of a bowl at 0.7 m: colour/NNNN.png, depth/NNNN.png (mm), tum/ (the same frames
// as a TUM RGB-D folder, depth in 1/5000 m), init.txt and camera.yaml.
Clip write_clip() {
  Clip clip;
  clip.dir = fs::path(testing::TempDir()) /
             ("scbt_cli_depth_" + std::to_string(::getpid()) + "_" +
              std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
  fs::remove_all(clip.dir);
  for (const char* sub : {"colour", "depth", "tum/rgb", "tum/depth"})
    fs::create_directories(clip.dir / sub);
  RgbdSceneOptions scene;
  RimPathOptions path;
  path.start = {-0.02, 0.0, 0.7};
  path.end = {0.02, 0.01, 0.72};
  path.sway = 0.004;
  DepthSensorOptions sensor;
  std::ofstream rgb_list(clip.dir / "tum/rgb.txt"), depth_list(clip.dir / "tum/depth.txt");
  rgb_list << "# color images\n";
  depth_list << "# depth maps\n";
  const std::vector<RimPose> poses = rim_path(path, 12);
  for (int i = 0; i < static_cast<int>(poses.size()); ++i) {
    const RgbdFrame frame = render_rgbd_frame(scene, poses[i], i);
    const cv::Mat depth = apply_depth_sensor(frame.clean_depth, frame.truth, sensor, i);
    cv::imwrite((clip.dir / "colour" / number_name(i + 1)).string(), frame.colour);
    cv::imwrite((clip.dir / "depth" / number_name(i + 1)).string(), depth);
    char stamp[32];
    std::snprintf(stamp, sizeof stamp, "%.6f", 100.0 + i / 30.0);
    cv::imwrite((clip.dir / "tum/rgb" / (std::string(stamp) + ".png")).string(), frame.colour);
    cv::Mat tum_depth;
    depth.convertTo(tum_depth, CV_16U, 5.0);  // TUM: 5000 units per metre
    std::snprintf(stamp, sizeof stamp, "%.6f", 100.0 + i / 30.0 + 0.004);
    cv::imwrite((clip.dir / "tum/depth" / (std::string(stamp) + ".png")).string(), tum_depth);
    std::snprintf(stamp, sizeof stamp, "%.6f", 100.0 + i / 30.0);
    rgb_list << stamp << " rgb/" << stamp << ".png\n";
    std::snprintf(stamp, sizeof stamp, "%.6f", 100.0 + i / 30.0 + 0.004);
    depth_list << stamp << " depth/" << stamp << ".png\n";
    if (i == 0) std::ofstream(clip.dir / "init.txt") << format_polygon_line(frame.truth) << '\n';
    clip.centres.push_back(frame.centre);
    clip.normals.push_back(frame.normal);
  }
  std::ofstream(clip.dir / "camera.yaml")
      << "image_width: 640\nimage_height: 480\ncamera_matrix:\n  rows: 3\n  cols: 3\n"
      << "  data: [525, 0, 319.5, 0, 525, 239.5, 0, 0, 1]\ndistortion_model: plumb_bob\n"
      << "distortion_coefficients:\n  rows: 1\n  cols: 5\n  data: [0, 0, 0, 0, 0]\n";
  return clip;
}

int run(const Clip& clip, const std::string& args, std::string* err) {
  const cli_test::RunResult r = cli_test::run_scbt(clip.dir, "track " + args + " -q");
  *err = r.err;
  return r.exit_code;
}

// The CSV's rows as numbers (nan kept), after checking the header.
std::vector<std::vector<double>> read_points3d(const fs::path& path) {
  std::ifstream file(path);
  std::string line;
  std::getline(file, line);
  EXPECT_EQ(line, "frame,valid,x,y,z,nx,ny,nz,radius,rms,n_valid,n_samples");
  std::vector<std::vector<double>> rows;
  while (std::getline(file, line)) {
    std::vector<double> row;
    std::stringstream fields(line);
    std::string field;
    while (std::getline(fields, field, ',')) row.push_back(std::strtod(field.c_str(), nullptr));
    rows.push_back(row);
  }
  return rows;
}

void expect_accurate(const Clip& clip, const std::vector<std::vector<double>>& rows) {
  ASSERT_EQ(rows.size(), clip.centres.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].size(), 12u);
    EXPECT_EQ(rows[i][0], static_cast<double>(i + 1));
    ASSERT_EQ(rows[i][1], 1.0) << "frame " << i + 1;
    const Eigen::Vector3d centroid(rows[i][2], rows[i][3], rows[i][4]);
    const Eigen::Vector3d normal(rows[i][5], rows[i][6], rows[i][7]);
    EXPECT_LT((centroid - clip.centres[i]).norm(), 0.003) << "frame " << i + 1;
    EXPECT_GT(normal.dot(clip.normals[i]), std::cos(2.0 * M_PI / 180.0)) << "frame " << i + 1;
    EXPECT_NEAR(rows[i][8], 0.1, 0.002) << "frame " << i + 1;
  }
}

TEST(CliDepth, NumberedDepthFolderAndTumFolder) {
  const Clip clip = write_clip();
  std::string err;
  ASSERT_EQ(run(clip,
                "colour --init init.txt -o results.txt --depth depth --intrinsics "
                "525,525,319.5,239.5 --points3d points.csv --boundary3d rim.txt --video out.avi",
                &err),
            0)
      << err;
  expect_accurate(clip, read_points3d(clip.dir / "points.csv"));
  std::ifstream rim(clip.dir / "rim.txt");
  int lines = 0, count = 0;
  for (std::string line; std::getline(rim, line); ++lines) {
    std::stringstream(line) >> count;
    EXPECT_GT(count, 50);
  }
  EXPECT_EQ(lines, 12);
  EXPECT_TRUE(fs::exists(clip.dir / "out.avi"));

  ASSERT_EQ(run(clip,
                "tum --init init.txt -o tum_results.txt --depth tum --camera-info camera.yaml "
                "--depth-scale 0.0002 --points3d tum_points.csv",
                &err),
            0)
      << err;
  expect_accurate(clip, read_points3d(clip.dir / "tum_points.csv"));
}

TEST(CliDepth, ClearErrorsForBadDepthInput) {
  const Clip clip = write_clip();
  struct Case {
    std::string args, message;
    int exit_code;  // 2: bad command line, 1: bad input data
  };
  const std::string base = "colour --init init.txt -o r.txt ";
  const std::vector<Case> cases = {
      {base + "--depth depth --points3d p.csv", "--intrinsics fx,fy,cx,cy or --camera-info", 2},
      {base + "--depth depth --intrinsics 525,525,319.5 --points3d p.csv", "--intrinsics", 2},
      {base + "--depth nowhere --intrinsics 525,525,319.5,239.5 --points3d p.csv", "nowhere", 1},
      {base + "--depth depth --camera-info missing.yaml --points3d p.csv", "missing.yaml", 1},
      {base + "--depth depth --intrinsics 525,525,319.5,239.5", "--points3d", 2},
      {base + "--points3d p.csv --intrinsics 525,525,319.5,239.5", "--depth", 2},
      {base + "--depth colour --intrinsics 525,525,319.5,239.5 --points3d p.csv", "16-bit", 1},
      {base + "--depth depth --intrinsics 525,525,319.5,239.5 --depth-scale 0 --points3d p.csv",
       "depth_scale", 2},
      {base + "--depth depth --intrinsics 525,525,319.5,239.5 --points3d r.txt", "r.txt", 2},
      {"tum --init init.txt -o r.txt --depth tum --intrinsics 525,525,319.5,239.5 --points3d "
       "p.csv",
       "", 0},
      {"colour --init init.txt -o r.txt --depth tum --intrinsics 525,525,319.5,239.5 --points3d "
       "p.csv",
       "INPUT must be that folder too", 2},
      // Read with a limit (an endless file stops there), and the limit is named.
      {base + "--depth depth --camera-info endless.yaml --points3d p.csv",
       "endless.yaml: larger than 1 MiB, the limit for a camera info file", 1},
      {base + "--depth depth --camera-info depth --points3d p.csv",
       "depth: is a folder, not a file", 1},
      {base + "--depth float_depth --intrinsics 525,525,319.5,239.5 --points3d p.csv",
       "a depth image must be single-channel 16-bit unsigned (depth units, --depth-scale metres "
       "each), got 1 channel of 32-bit float",
       1},
      {base + "--depth depth --intrinsics 525,525,319.5,239.5 --depth-scale 1e308 --points3d p.csv",
       "--depth-scale 1e+308: a 16-bit depth image's values 1..65535 would be 1e+308..inf m, none "
       "of them within the valid depths 0.1..10 m",
       2},
      {base + "--depth depth --intrinsics 525,525,319.5,239.5 --depth-scale 1e-9 --points3d p.csv",
       "none of them within the valid depths", 2},
  };
  fs::create_symlink("/dev/zero", clip.dir / "endless.yaml");
  fs::create_directory(clip.dir / "float_depth");
  for (const fs::directory_entry& e : fs::directory_iterator(clip.dir / "depth")) {
    cv::Mat depth = cv::imread(e.path().string(), cv::IMREAD_UNCHANGED);
    depth.convertTo(depth, CV_32F, 0.001);
    const fs::path tiff = clip.dir / "float_depth" / e.path().filename().replace_extension(".tif");
    ASSERT_TRUE(cv::imwrite(tiff.string(), depth));
  }
  for (const Case& c : cases) {
    std::string err;
    const int code = run(clip, c.args, &err);
    if (c.exit_code == 0) {  // the reference case: these options work
      EXPECT_EQ(code, 0) << c.args << "\n" << err;
      fs::remove(clip.dir / "p.csv");
      fs::remove(clip.dir / "r.txt");
      continue;
    }
    EXPECT_EQ(code, c.exit_code) << c.args << "\n" << err;
    EXPECT_NE(err.find("scbt: error:"), std::string::npos) << c.args << "\n" << err;
    EXPECT_NE(err.find(c.message), std::string::npos) << c.args << "\n" << err;
    EXPECT_FALSE(fs::exists(clip.dir / "p.csv")) << c.args;
    EXPECT_FALSE(fs::exists(clip.dir / "r.txt")) << c.args;
  }
}

}  // namespace
}  // namespace scbt
