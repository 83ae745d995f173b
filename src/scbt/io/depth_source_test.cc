#include "scbt/io/depth_source.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

namespace scbt {
namespace {
namespace fs = std::filesystem;

fs::path fresh_folder(const std::string& name) {
  // The process id keeps concurrent test runs (two build folders) out of each other's files.
  const fs::path folder = fs::path(testing::TempDir()) / (std::to_string(::getpid()) + "_" + name);
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

TEST(DepthSource, NumberedFolderOfSixteenBitImages) {
  const fs::path folder = fresh_folder("scbt_depth_numbered");
  for (int i = 1; i <= 3; ++i)
    cv::imwrite((folder / ("000" + std::to_string(i) + ".png")).string(),
                cv::Mat(4, 5, CV_16UC1, cv::Scalar(1000 * i)));
  const DepthSource source(folder.string());
  EXPECT_FALSE(source.is_tum());
  ASSERT_EQ(source.size(), 3);
  EXPECT_EQ(source.read(1).at<std::uint16_t>(0, 0), 2000);
  EXPECT_TRUE(source.read(3).empty());  // past the end: no depth for that frame
  cv::imwrite((folder / "0004.png").string(), cv::Mat(4, 5, CV_8UC1, cv::Scalar(9)));
  EXPECT_THROW(DepthSource(folder.string()).read(3), std::runtime_error);         // 8-bit
  EXPECT_THROW(DepthSource((folder / "0001.png").string()), std::runtime_error);  // a file
  fs::remove_all(folder);
}

TEST(DepthSource, TumFolderAssociatedByTimestamp) {
  const fs::path folder = fresh_folder("scbt_depth_tum");
  fs::create_directories(folder / "rgb");
  fs::create_directories(folder / "depth");
  std::ofstream(folder / "rgb.txt") << "# color images\n# timestamp filename\n"
                                    << "10.000 rgb/10.000.png\n10.033 rgb/10.033.png\n"
                                    << "10.500 rgb/10.500.png\n";
  std::ofstream(folder / "depth.txt") << "# depth maps\n10.010 depth/10.010.png\n"
                                      << "10.040 depth/10.040.png\n";
  cv::imwrite((folder / "depth/10.010.png").string(), cv::Mat(2, 2, CV_16UC1, cv::Scalar(5000)));
  cv::imwrite((folder / "depth/10.040.png").string(), cv::Mat(2, 2, CV_16UC1, cv::Scalar(6000)));
  ASSERT_TRUE(is_tum_rgbd_folder(folder.string()));
  const DepthSource source(folder.string());
  EXPECT_TRUE(source.is_tum());
  ASSERT_EQ(source.colour_files().size(), 3u);
  EXPECT_EQ(fs::path(source.colour_files()[1]).filename(), "10.033.png");
  EXPECT_EQ(source.read(0).at<std::uint16_t>(0, 0), 5000);
  EXPECT_EQ(source.read(1).at<std::uint16_t>(0, 0), 6000);
  EXPECT_TRUE(source.read(2).empty());  // nothing within 0.02 s of 10.5
  std::ofstream(folder / "depth.txt") << "10.010 depth/10.010.png\nnot-a-number x\n";
  EXPECT_THROW(DepthSource(folder.string()), std::runtime_error);
  fs::remove_all(folder);
}

}  // namespace
}  // namespace scbt
