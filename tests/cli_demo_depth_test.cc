// `scbt demo --depth` end to end: the built binary renders a short RGB-D clip of a bowl, tracks
// it, lifts it to 3-D and prints its errors and the `scbt track --depth` command for the clip;
// that command, run as printed, must give the same 3-D rows, and both must be near the truth the
// demo wrote.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_test_util.h"

namespace scbt {
namespace {

namespace fs = std::filesystem;

struct Output {
  int exit_code = -1;
  std::string out, err;
};

// Runs `command` (shell code) in `dir`, capturing both streams.
Output run_in(const fs::path& dir, const std::string& command) {
  const std::string line = "cd '" + dir.string() + "' && " + command + " > '" +
                           (dir / "stdout.txt").string() + "' 2> '" +
                           (dir / "stderr.txt").string() + "'";
  const int status = std::system(line.c_str());
  Output output;
  output.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 1000 + WTERMSIG(status);
  output.out = cli_test::read_file(dir / "stdout.txt");
  output.err = cli_test::read_file(dir / "stderr.txt");
  return output;
}

std::vector<std::vector<double>> read_csv(const fs::path& path, const std::string& header) {
  std::ifstream file(path);
  std::string line;
  std::getline(file, line);
  EXPECT_EQ(line, header) << path;
  std::vector<std::vector<double>> rows;
  while (std::getline(file, line)) {
    std::vector<double> row;
    std::stringstream fields(line);
    for (std::string field; std::getline(fields, field, ',');)
      row.push_back(std::strtod(field.c_str(), nullptr));
    rows.push_back(row);
  }
  return rows;
}

const char kPointsHeader[] = "frame,valid,x,y,z,nx,ny,nz,radius,rms,n_valid,n_samples";

TEST(CliDemoDepth, PrintsItsErrorsAndTheTrackCommandThatReproducesThem) {
  const fs::path dir = cli_test::fresh_test_dir("scbt_demo_depth");
  const std::string binary = "'" + std::string(SCBT_BINARY) + "'";
  const Output demo = run_in(dir, binary + " demo --depth --frames 8 --out clip --seed 3");
  ASSERT_EQ(demo.exit_code, 0) << demo.err;
  EXPECT_NE(demo.out.find("centroid"), std::string::npos) << demo.out;
  EXPECT_NE(demo.out.find("normal"), std::string::npos) << demo.out;
  EXPECT_NE(demo.out.find("radius"), std::string::npos) << demo.out;
  EXPECT_NE(demo.out.find("frames 8, 3-D rim valid in 8"), std::string::npos) << demo.out;
  for (const char* file : {"colour/0001.png", "colour/0008.png", "depth/0008.png", "init.txt",
                           "truth3d.csv", "points3d.csv"})
    EXPECT_TRUE(fs::exists(dir / "clip" / file)) << file;

  // The last line of the summary is the command; run it with this binary.
  const std::vector<std::string> lines = cli_test::read_text_lines_of(demo.out);
  ASSERT_FALSE(lines.empty());
  std::string command = lines.back();
  const std::string prefix = "  scbt track ";
  ASSERT_EQ(command.rfind(prefix, 0), 0u) << command;
  EXPECT_NE(command.find("--depth clip/depth"), std::string::npos) << command;
  command = binary + " track " + command.substr(prefix.size()) + " -q";
  const Output track = run_in(dir, command);
  ASSERT_EQ(track.exit_code, 0) << command << "\n" << track.err;

  const auto truth = read_csv(dir / "clip/truth3d.csv", "frame,x,y,z,nx,ny,nz,radius");
  const auto demo_rows = read_csv(dir / "clip/points3d.csv", kPointsHeader);
  const auto track_rows = read_csv(dir / "clip/tracked3d.csv", kPointsHeader);
  ASSERT_EQ(truth.size(), 8u);
  ASSERT_EQ(demo_rows.size(), 8u);
  ASSERT_EQ(track_rows.size(), 8u);
  for (std::size_t i = 0; i < truth.size(); ++i) {
    ASSERT_EQ(demo_rows[i].size(), 12u);
    ASSERT_EQ(track_rows[i].size(), 12u);
    for (std::size_t k = 0; k < 12; ++k)  // the same lift, to the CSV's precision
      EXPECT_NEAR(demo_rows[i][k], track_rows[i][k], 1e-6) << "frame " << i + 1 << " col " << k;
    ASSERT_EQ(demo_rows[i][1], 1.0) << "frame " << i + 1;
    double distance = 0.0, cosine = 0.0;
    for (int k = 0; k < 3; ++k) {
      distance += std::pow(demo_rows[i][2 + k] - truth[i][1 + k], 2);
      cosine += demo_rows[i][5 + k] * truth[i][4 + k];
    }
    EXPECT_LT(std::sqrt(distance), 0.004) << "frame " << i + 1;
    EXPECT_GT(cosine, std::cos(2.0 * M_PI / 180.0)) << "frame " << i + 1;
    EXPECT_NEAR(demo_rows[i][8], truth[i][7], 0.02 * truth[i][7]) << "frame " << i + 1;
  }
  fs::remove_all(dir);
}

TEST(CliDemoDepth, OptionsOfTheTwoDimensionalDemoAreRefused) {
  const fs::path dir = cli_test::fresh_test_dir("scbt_demo_depth");
  const std::string binary = "'" + std::string(SCBT_BINARY) + "'";
  for (const std::string args : {"demo --depth --shape box", "demo --distance 1.0",
                                 "demo --depth --distance 5 --frames 3"}) {
    const Output output = run_in(dir, binary + " " + args);
    EXPECT_EQ(output.exit_code, 2) << args << "\n" << output.err;
    EXPECT_NE(output.err.find("scbt: error:"), std::string::npos) << args << "\n" << output.err;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace scbt
