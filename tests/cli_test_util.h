// Running the built `scbt` binary from whole-program tests (SCBT_BINARY names it).
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#ifndef SCBT_BINARY
#error "SCBT_BINARY must name the scbt executable"
#endif

namespace scbt::cli_test {

inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

inline std::vector<std::string> read_text_lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream stream(text);
  for (std::string line; std::getline(stream, line);) lines.push_back(line);
  return lines;
}

// An empty folder for the running test: <temp>/<prefix>_<test name>_<pid>.
inline std::filesystem::path fresh_test_dir(const std::string& prefix) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() /
      (prefix + "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name() + "_" +
       std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

struct RunResult {
  int exit_code = -1;
  std::string err;  // stderr
};

// Runs scbt with `args` (already shell-quoted) in `dir`, capturing stderr; `prefix` is shell
// code run first in the same shell (limits, traps).
inline RunResult run_scbt(const std::filesystem::path& dir, const std::string& args,
                          const std::string& prefix = "") {
  const std::filesystem::path err = dir / "stderr.txt";
  const std::string command = "cd '" + dir.string() + "' && " + prefix + " '" +
                              std::string(SCBT_BINARY) + "' " + args + " 2> '" + err.string() +
                              "' > /dev/null";
  const int status = std::system(command.c_str());
  RunResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 1000 + WTERMSIG(status);
  result.err = read_file(err);
  return result;
}

}  // namespace scbt::cli_test
