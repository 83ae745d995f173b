#include "scbt/io/output_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "scbt/io/bounded_read.h"

namespace scbt {
namespace {

// Opens the file that `target` is written through: standard output as it is, an in-place
// output itself, a regular file's fresh temporary sibling (with the old file's permissions).
int open_output(const OutputTarget& target, std::string* temporary) {
  switch (target.kind) {
    case OutputKind::kStdout:
      return STDOUT_FILENO;
    case OutputKind::kInPlace: {
      // No O_TRUNC: a device or FIFO has nothing to truncate, and O_CREAT could not apply. A
      // FIFO waits in open() for its reader; a stop signal ends the wait (EINTR).
      int fd = -1;
      do {
        throw_if_stop_requested(printable(target.path) + ": waiting for a reader");
        fd = ::open(target.target.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
      } while (fd < 0 && errno == EINTR);
      if (fd < 0) {
        throw std::runtime_error(printable(target.path) +
                                 ": cannot open for writing: " + std::strerror(errno));
      }
      return fd;
    }
    case OutputKind::kReplace:
      break;
  }
  const int fd = create_temporary_sibling(target.target, "", target.path, temporary);
  try {
    copy_permissions(fd, target);
  } catch (...) {
    ::close(fd);
    ::unlink(temporary->c_str());
    throw;
  }
  return fd;
}

}  // namespace

FdStreamBuffer::FdStreamBuffer(int fd) : fd_(fd), buffer_(1 << 16) {
  setp(buffer_.data(), buffer_.data() + buffer_.size());
}

bool FdStreamBuffer::drain() {
  const char* next = pbase();
  size_t left = static_cast<size_t>(pptr() - pbase());
  setp(buffer_.data(), buffer_.data() + buffer_.size());
  if (error_ != 0) return false;  // after a failure, nothing more is written
  while (left > 0) {
    const ssize_t written = ::write(fd_, next, left);
    if (written < 0) {
      if (errno == EINTR) continue;
      error_ = errno;
      return false;
    }
    next += written;
    left -= static_cast<size_t>(written);
  }
  return true;
}

FdStreamBuffer::int_type FdStreamBuffer::overflow(int_type ch) {
  if (!drain()) return traits_type::eof();
  if (!traits_type::eq_int_type(ch, traits_type::eof())) {
    *pptr() = traits_type::to_char_type(ch);
    pbump(1);
  }
  return traits_type::not_eof(ch);
}

OutputFile::OutputFile(std::string path)
    : target_(classify_output(path)),
      fd_(open_output(target_, &temporary_)),
      buffer_(fd_),
      stream_(&buffer_) {}

OutputFile::~OutputFile() {
  if (!finished_) {
    if (target_.kind == OutputKind::kStdout) {
      buffer_.drain();  // what was streamed so far is the reader's
    } else {
      ::close(fd_);
    }
  }
  if (!published_ && !temporary_.empty()) ::unlink(temporary_.c_str());
}

void OutputFile::end_record() {
  if (target_.kind != OutputKind::kReplace) stream_.flush();
}

void OutputFile::finish() {
  if (finished_) return;
  finished_ = true;
  bool ok = buffer_.drain();
  int error = buffer_.error();
  if (target_.kind == OutputKind::kReplace && ok && ::fsync(fd_) != 0) {
    ok = false;
    error = errno;
  }
  if (target_.kind != OutputKind::kStdout && ::close(fd_) != 0 && ok) {
    ok = false;
    error = errno;
  }
  if (!ok && !(error == EPIPE && target_.kind != OutputKind::kReplace)) {
    throw std::runtime_error(printable(target_.path) + ": write failed: " + std::strerror(error));
  }
}

void OutputFile::publish() {
  if (!finished_) throw std::logic_error("OutputFile::publish before finish");
  if (published_ || temporary_.empty()) return;
  if (std::rename(temporary_.c_str(), target_.target.c_str()) != 0) {
    throw std::runtime_error(printable(target_.path) +
                             ": cannot move the finished file into place: " + std::strerror(errno));
  }
  published_ = true;
}

}  // namespace scbt
