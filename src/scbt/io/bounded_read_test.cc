#include "scbt/io/bounded_read.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

namespace scbt {
namespace {

namespace fs = std::filesystem;

fs::path temp_path(const std::string& name) {
  return fs::temp_directory_path() /
         ("scbt_bounded_read_" + std::to_string(::getpid()) + "_" + name);
}

std::string message_of(const std::function<void()>& body) {
  try {
    body();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(BoundedRead, ReadsAFileUpToItsLimit) {
  const fs::path path = temp_path("exact");
  std::ofstream(path, std::ios::binary) << std::string(1000, 'x');
  EXPECT_EQ(read_file_bounded(path.string(), {1000, "a test file"}).size(), 1000u);
  EXPECT_EQ(message_of([&] {
              read_file_bounded(path.string(), {999, "a test file"});
            }),
            path.string() + ": 1000 bytes, over the 999 bytes limit for a test file");
  fs::remove(path);
}

// An endless file stops at the limit, and the error names it.
TEST(BoundedRead, AnEndlessFileStopsAtTheLimit) {
  EXPECT_EQ(message_of([] {
              read_file_bounded("/dev/zero", {1 << 20, "a camera info file"});
            }),
            "/dev/zero: larger than 1 MiB, the limit for a camera info file");
}

// A sparse file of 2 GiB is refused by its size, before anything is read.
TEST(BoundedRead, AHugeSparseFileIsRefusedByItsSize) {
  const fs::path path = temp_path("sparse");
  { std::ofstream(path, std::ios::binary) << "x"; }
  fs::resize_file(path, std::uintmax_t{2} << 30);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(message_of([&] {
              read_file_bounded(path.string(), {1 << 20, "a camera info file"});
            }),
            path.string() + ": 2147483648 bytes, over the 1 MiB limit for a camera info file");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
  fs::remove(path);
}

TEST(BoundedRead, AFolderIsNamedAsOne) {
  EXPECT_EQ(message_of([] { read_file_bounded("/tmp", {}); }), "/tmp: is a folder, not a file");
  EXPECT_EQ(message_of([] { read_file_bounded("/nonexistent/x", {}); }),
            "/nonexistent/x: cannot open for reading: No such file or directory");
}

TEST(BoundedRead, LinesAreBoundedOneByOne) {
  const fs::path path = temp_path("lines");
  std::ofstream(path, std::ios::binary) << "one\r\ntwo\n\n" + std::string(100, 'z') + "\nlast";
  BoundedReader reader(path.string(), {});
  std::string line;
  ASSERT_TRUE(reader.read_line(&line, 10));
  EXPECT_EQ(line, "one\r");
  ASSERT_TRUE(reader.read_line(&line, 10));
  EXPECT_EQ(line, "two");
  ASSERT_TRUE(reader.read_line(&line, 10));
  EXPECT_EQ(line, "");
  EXPECT_EQ(message_of([&] { reader.read_line(&line, 10); }),
            path.string() + ":4: line longer than 10 bytes");
  fs::remove(path);

  BoundedReader zero("/dev/zero", {});
  EXPECT_EQ(message_of([&] { zero.read_line(&line, 1 << 20); }),
            "/dev/zero:1: line longer than 1 MiB");
}

// A request to stop (from a signal handler) ends a read that would go on for long.
TEST(BoundedRead, AStopRequestEndsTheRead) {
  clear_stop_request();
  request_stop(SIGTERM);
  try {
    read_file_bounded("/dev/zero", {});
    ADD_FAILURE() << "not interrupted";
  } catch (const Interrupted& e) {
    EXPECT_EQ(e.signal_number(), SIGTERM);
    EXPECT_STREQ(e.what(), "/dev/zero: interrupted by SIGTERM");
  }
  clear_stop_request();
}

// A FIFO without a writer: the wait in open() ends when a signal interrupts it and the check
// says stop.
extern "C" void ignore_signal(int) {}

TEST(BoundedRead, AWaitForAFifoWriterIsInterruptible) {
  const fs::path path = temp_path("fifo");
  ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
  struct sigaction action {
  }, old{};
  action.sa_handler = ignore_signal;  // no SA_RESTART: open() returns EINTR
  sigemptyset(&action.sa_mask);
  sigaction(SIGUSR1, &action, &old);
  const pthread_t reader_thread = ::pthread_self();
  bool checked_after_signal = false;
  std::thread signaller([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    ::pthread_kill(reader_thread, SIGUSR1);
  });
  int checks = 0;
  const std::string message = message_of([&] {
    read_file_bounded(path.string(), {}, [&] {
      if (++checks > 1) {
        checked_after_signal = true;
        throw std::runtime_error("stopped");
      }
    });
  });
  signaller.join();
  sigaction(SIGUSR1, &old, nullptr);
  EXPECT_EQ(message, "stopped");
  EXPECT_TRUE(checked_after_signal);
  fs::remove(path);
}

TEST(BoundedRead, ByteSizesReadWell) {
  EXPECT_EQ(format_byte_size(1 << 20), "1 MiB");
  EXPECT_EQ(format_byte_size(std::size_t{256} << 20), "256 MiB");
  EXPECT_EQ(format_byte_size(std::size_t{1} << 30), "1 GiB");
  EXPECT_EQ(format_byte_size(1500), "1500 bytes");
}

}  // namespace
}  // namespace scbt
