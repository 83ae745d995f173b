// Reading a file the user named (polygons, results, ground truth, camera info, images) with a
// size limit checked while reading: a file may be huge, sparse, endless (/dev/zero) or a FIFO
// that never ends, and none of these may take unbounded memory or time. Every read can be
// stopped by a signal that asks the process to stop (SIGINT, SIGTERM, SIGHUP), also while it
// waits on a FIFO. Errors name the file and, for a limit, which limit was hit.
#pragma once

#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>

namespace scbt {

// The limits of the files scbt reads (each far beyond any real file of its kind).
constexpr std::size_t kMaxCameraInfoBytes = std::size_t{1} << 20;  // 1 MiB
constexpr std::size_t kMaxTextFileBytes = std::size_t{256} << 20;  // 256 MiB: polygons, results
constexpr std::size_t kMaxImageFileBytes = std::size_t{1} << 30;   // 1 GiB: a frame, a depth image

// How much of which kind of file may be read: "a camera info file", "a results file", ...
struct ReadLimit {
  std::size_t max_bytes = kMaxTextFileBytes;
  std::string what = "a text file";
};

// A read (or a wait to open a file) abandoned because a stop signal arrived (see request_stop).
class Interrupted : public std::runtime_error {
 public:
  Interrupted(const std::string& message, int signal_number)
      : std::runtime_error(message), signal_number_(signal_number) {}
  int signal_number() const { return signal_number_; }

 private:
  int signal_number_;
};

// The process-wide stop request. request_stop is async-signal-safe: a signal handler calls it,
// and every bounded read in progress (or started later) then throws Interrupted.
void request_stop(int signal_number) noexcept;
int stop_requested() noexcept;  // the signal that requested the stop, else 0
void clear_stop_request() noexcept;
// "SIGINT", "SIGTERM", "SIGHUP", else "a signal".
const char* signal_name(int signal_number);
// Throws Interrupted "WHAT: interrupted by SIGTERM" when a stop has been requested.
void throw_if_stop_requested(const std::string& what);

// Called before each read and each time a system call returns EINTR; it may throw to abandon
// the read (Python: a pending KeyboardInterrupt). Empty: the default, which throws
// Interrupted once request_stop has been called.
using InterruptCheck = std::function<void()>;

// "1 MiB", "256 MiB", "1 GiB", "1500 bytes".
std::string format_byte_size(std::size_t bytes);

// An open file read in bounded steps.
class BoundedReader {
 public:
  // Opens `path` for reading (a file, a FIFO: waiting for its writer, interruptibly; a device).
  // Throws std::runtime_error "PATH: cannot open for reading: <reason>", "PATH: is a folder, not
  // a file", or "PATH: N bytes, over the LIMIT limit for WHAT" when a regular file is larger
  // than the limit before anything is read.
  BoundedReader(const std::string& path, ReadLimit limit, InterruptCheck check = {});
  ~BoundedReader();
  BoundedReader(const BoundedReader&) = delete;
  BoundedReader& operator=(const BoundedReader&) = delete;

  // Reads the rest of the file. Throws std::runtime_error "PATH: larger than LIMIT, the limit
  // for WHAT" as soon as the bytes read pass the limit, "PATH: read error: <reason>" on failure.
  std::string read_all();
  // The next line without its '\n' (a trailing '\r' is kept); false at the end of the file.
  // Throws "PATH:N: line longer than MAX" when a line passes `max_line` bytes, and as read_all.
  bool read_line(std::string* line, std::size_t max_line);
  // The number of the line read_line returned last (1-based).
  long line_number() const { return line_number_; }
  const std::string& path() const { return path_; }

 private:
  bool fill();  // reads more into buffer_; false at the end of the file
  void check_interrupt() const;

  std::string path_;
  ReadLimit limit_;
  InterruptCheck check_;
  int fd_ = -1;
  std::size_t total_ = 0;  // bytes read from the file so far
  std::string buffer_;     // read but not yet returned
  std::size_t start_ = 0;  // buffer_'s first byte not yet returned
  bool at_end_ = false;
  long line_number_ = 0;
};

// The whole file, at most limit.max_bytes of it (BoundedReader::read_all).
std::string read_file_bounded(const std::string& path, const ReadLimit& limit,
                              const InterruptCheck& check = {});

}  // namespace scbt
