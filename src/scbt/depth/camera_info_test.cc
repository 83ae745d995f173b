#include "scbt/depth/camera_info.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <opencv2/core.hpp>
#include <stdexcept>
#include <string>

namespace scbt {
namespace {

std::string write_temp(const std::string& name, const std::string& text) {
  // The process id keeps concurrent test runs (two build folders) out of each other's files.
  const std::string path = testing::TempDir() + std::to_string(::getpid()) + "_" + name;
  std::ofstream(path) << text;
  return path;
}

TEST(CameraInfo, ReadsRosCameraInfoYaml) {
  const std::string path = write_temp("ros_camera_info.yaml", R"(image_width: 640
image_height: 480
camera_name: rgb_camera
camera_matrix:
  rows: 3
  cols: 3
  data: [520.5, 0, 321.2, 0, 519.0, 243.7, 0, 0, 1]
distortion_model: plumb_bob
distortion_coefficients:
  rows: 1
  cols: 5
  data: [0.1, -0.2, 0.001, 0.002, 0.05]
rectification_matrix:
  rows: 3
  cols: 3
  data: [1, 0, 0, 0, 1, 0, 0, 0, 1]
)");
  const PinholeIntrinsics camera = read_camera_info(path);
  EXPECT_DOUBLE_EQ(camera.fx, 520.5);
  EXPECT_DOUBLE_EQ(camera.fy, 519.0);
  EXPECT_DOUBLE_EQ(camera.cx, 321.2);
  EXPECT_DOUBLE_EQ(camera.cy, 243.7);
  ASSERT_EQ(camera.distortion.size(), 5u);
  EXPECT_DOUBLE_EQ(camera.distortion[4], 0.05);
  std::remove(path.c_str());
}

TEST(CameraInfo, ReadsOpenCvCalibrationFile) {
  const std::string path =
      testing::TempDir() + std::to_string(::getpid()) + "_opencv_calibration.yml";
  {
    cv::FileStorage storage(path, cv::FileStorage::WRITE);
    storage << "camera_matrix" << (cv::Mat_<double>(3, 3) << 600, 0, 330, 0, 601, 250, 0, 0, 1);
    storage << "distortion_coefficients" << (cv::Mat_<double>(1, 4) << 0.01, 0.02, 0.0, 0.0);
  }
  const PinholeIntrinsics camera = read_camera_info(path);
  EXPECT_DOUBLE_EQ(camera.fx, 600.0);
  EXPECT_DOUBLE_EQ(camera.fy, 601.0);
  EXPECT_DOUBLE_EQ(camera.cx, 330.0);
  EXPECT_DOUBLE_EQ(camera.cy, 250.0);
  EXPECT_EQ(camera.distortion.size(), 4u);
  std::remove(path.c_str());
}

TEST(CameraInfo, ClearErrorsForBadFiles) {
  EXPECT_THROW(read_camera_info(testing::TempDir() + "does_not_exist.yaml"), std::runtime_error);
  const std::string no_matrix = write_temp("no_matrix.yaml", "image_width: 640\n");
  EXPECT_THROW(read_camera_info(no_matrix), std::runtime_error);
  const std::string short_matrix = write_temp(
      "short_matrix.yaml", "camera_matrix:\n  rows: 2\n  cols: 2\n  data: [1, 0, 0, 1]\n");
  EXPECT_THROW(read_camera_info(short_matrix), std::runtime_error);
  const std::string fisheye = write_temp("fisheye.yaml",
                                         "camera_matrix:\n  data: [500, 0, 320, 0, 500, 240, 0, 0, "
                                         "1]\ndistortion_model: equidistant\n");
  EXPECT_THROW(read_camera_info(fisheye), std::runtime_error);
  for (const std::string& path : {no_matrix, short_matrix, fisheye}) std::remove(path.c_str());
}

}  // namespace
}  // namespace scbt
