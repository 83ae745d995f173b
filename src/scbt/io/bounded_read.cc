#include "scbt/io/bounded_read.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>

#include "scbt/io/printable.h"

namespace scbt {
namespace {

volatile std::sig_atomic_t g_stop_request = 0;

constexpr std::size_t kChunk = 1 << 16;

std::runtime_error error_for(const std::string& path, const std::string& what) {
  return std::runtime_error(printable(path) + ": " + what);
}

}  // namespace

void request_stop(int signal_number) noexcept { g_stop_request = signal_number; }
int stop_requested() noexcept { return g_stop_request; }
void clear_stop_request() noexcept { g_stop_request = 0; }

void throw_if_stop_requested(const std::string& what) {
  const int signal_number = stop_requested();
  if (signal_number != 0) {
    throw Interrupted(what + ": interrupted by " + signal_name(signal_number), signal_number);
  }
}

std::string format_byte_size(std::size_t bytes) {
  if (bytes >= (std::size_t{1} << 30) && bytes % (std::size_t{1} << 30) == 0) {
    return std::to_string(bytes >> 30) + " GiB";
  }
  if (bytes >= (std::size_t{1} << 20) && bytes % (std::size_t{1} << 20) == 0) {
    return std::to_string(bytes >> 20) + " MiB";
  }
  if (bytes >= (std::size_t{1} << 10) && bytes % (std::size_t{1} << 10) == 0) {
    return std::to_string(bytes >> 10) + " KiB";
  }
  return std::to_string(bytes) + " bytes";
}

BoundedReader::BoundedReader(const std::string& path, ReadLimit limit, InterruptCheck check)
    : path_(path), limit_(std::move(limit)), check_(std::move(check)) {
  // A FIFO blocks in open() until a writer comes: a stop signal interrupts the wait (EINTR).
  for (;;) {
    check_interrupt();
    fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY);
    if (fd_ >= 0) break;
    if (errno == EINTR) continue;
    throw error_for(path, std::string("cannot open for reading: ") + std::strerror(errno));
  }
  struct stat info {};
  if (::fstat(fd_, &info) != 0) {
    const int error = errno;
    ::close(fd_);
    throw error_for(path, std::string("cannot examine: ") + std::strerror(error));
  }
  if (S_ISDIR(info.st_mode)) {
    ::close(fd_);
    throw error_for(path, "is a folder, not a file");
  }
  // A regular file's size is known (a sparse one need not be read to be refused).
  if (S_ISREG(info.st_mode) && static_cast<std::size_t>(info.st_size) > limit_.max_bytes) {
    ::close(fd_);
    throw error_for(path, std::to_string(info.st_size) + " bytes, over the " +
                              format_byte_size(limit_.max_bytes) + " limit for " + limit_.what);
  }
}

BoundedReader::~BoundedReader() {
  if (fd_ >= 0) ::close(fd_);
}

void BoundedReader::check_interrupt() const {
  if (check_) {
    check_();
    return;
  }
  throw_if_stop_requested(printable(path_));
}

bool BoundedReader::fill() {
  if (at_end_) return false;
  if (start_ > 0) {
    buffer_.erase(0, start_);
    start_ = 0;
  }
  const std::size_t old_size = buffer_.size();
  // One byte past the limit tells a file of exactly the limit from a larger one.
  const std::size_t room = limit_.max_bytes + 1 - total_;
  const std::size_t want = std::min(kChunk, room);
  buffer_.resize(old_size + want);
  for (;;) {
    check_interrupt();
    const ssize_t got = ::read(fd_, &buffer_[old_size], want);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) {
      const int error = errno;
      buffer_.resize(old_size);
      throw error_for(path_, std::string("read error: ") + std::strerror(error));
    }
    buffer_.resize(old_size + static_cast<std::size_t>(got));
    total_ += static_cast<std::size_t>(got);
    if (got == 0) {
      at_end_ = true;
      return false;
    }
    break;
  }
  if (total_ > limit_.max_bytes) {
    throw error_for(path_, "larger than " + format_byte_size(limit_.max_bytes) +
                               ", the limit for " + limit_.what);
  }
  return true;
}

std::string BoundedReader::read_all() {
  while (fill()) {
  }
  std::string rest = buffer_.substr(start_);
  buffer_.clear();
  start_ = 0;
  return rest;
}

bool BoundedReader::read_line(std::string* line, std::size_t max_line) {
  std::size_t searched = start_;
  for (;;) {
    const std::size_t newline = buffer_.find('\n', searched);
    if (newline != std::string::npos && newline - start_ <= max_line) {
      ++line_number_;
      line->assign(buffer_, start_, newline - start_);
      start_ = newline + 1;
      return true;
    }
    if (buffer_.size() - start_ > max_line) {
      throw std::runtime_error(printable(path_) + ":" + std::to_string(line_number_ + 1) +
                               ": line longer than " + format_byte_size(max_line));
    }
    searched = buffer_.size();
    const std::size_t kept = start_;
    if (!fill()) {
      if (buffer_.size() == start_) return false;
      ++line_number_;
      line->assign(buffer_, start_, std::string::npos);
      start_ = buffer_.size();
      return true;
    }
    searched -= kept;  // fill() moved the unread bytes to the front
  }
}

std::string read_file_bounded(const std::string& path, const ReadLimit& limit,
                              const InterruptCheck& check) {
  BoundedReader reader(path, limit, check);
  return reader.read_all();
}

const char* signal_name(int signal_number) {
  switch (signal_number) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    case SIGHUP:
      return "SIGHUP";
    default:
      return "a signal";
  }
}

}  // namespace scbt
