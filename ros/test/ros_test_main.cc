// main() of ros_node_test: a rosmaster of the test's own on a free loopback port (torn down
// after), this process a ROS node spinning in the background, then the test cases. Exits 77
// (ctest: skipped) when rosmaster is not installed, 1 under CI=true (scbt/app/ci_requirement.h).
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>

#include "node_under_test.h"
#include "ros_harness.h"
#include "scbt/app/ci_requirement.h"

int main(int argc, char** argv) {
  using namespace scbt::ros_test;
  namespace fs = std::filesystem;
  ::testing::InitGoogleTest(&argc, argv);
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], "--node") == 0) g_node_path = argv[i + 1];
  }
  if (g_node_path.empty()) {
    std::cerr << "usage: ros_node_test --node PATH_TO_scbt_node [gtest options]\n";
    return 2;
  }
  if (!on_path("rosmaster")) {
    const bool ci = scbt::ci_requires_everything();
    std::cerr << (ci ? "FAILED (CI=true): " : "SKIPPED (under CI=true this fails): ")
              << "rosmaster not found (python3-rosmaster; scripts/setup.sh installs it)\n";
    return ci ? 1 : 77;
  }
  // ROS_HOME and ROS_LOG_DIR keep the logs out of the user's ~/.ros.
  const fs::path home = fs::temp_directory_path() / ("scbt_ros_test_" + std::to_string(getpid()));
  fs::create_directories(home);
  g_log_folder = home.string();
  const int port = free_loopback_port();
  const std::string master_uri = "http://127.0.0.1:" + std::to_string(port);
  setenv("ROS_MASTER_URI", master_uri.c_str(), 1);
  setenv("ROS_IP", "127.0.0.1", 1);
  unsetenv("ROS_HOSTNAME");
  unsetenv("ROS_NAMESPACE");
  setenv("ROS_HOME", home.c_str(), 1);
  setenv("ROS_LOG_DIR", home.c_str(), 1);
  int result = 1;
  {
    ChildProcess master({"rosmaster", "--core", "-p", std::to_string(port)},
                        (home / "rosmaster.log").string());
    ros::init(argc, argv, "scbt_node_test",
              ros::init_options::NoSigintHandler | ros::init_options::AnonymousName);
    if (!wait_until([] { return ros::master::check(); }, std::chrono::milliseconds(20000))) {
      std::cerr << "rosmaster did not come up on " << master_uri << ":\n" << master.log();
      return 1;
    }
    std::cerr << "rosmaster at " << master_uri << ", logs in " << home << "\n";
    ros::AsyncSpinner spinner(2);
    spinner.start();
    result = RUN_ALL_TESTS();
    spinner.stop();
    ros::shutdown();
    master.stop();
  }
  if (result == 0) fs::remove_all(home);  // kept for reading when something failed
  return result;
}
