// A text output (results, CSV, report) that never destroys what the user has: written in place
// when it is standard output, a device, a FIFO or a socket; otherwise written to a temporary file
// beside its target and renamed onto it only on commit, so a failed or interrupted run leaves an
// existing file as it was and no temporary file behind.
#pragma once

#include <cerrno>
#include <memory>
#include <ostream>
#include <streambuf>
#include <string>
#include <vector>

#include "scbt/io/output_target.h"

namespace scbt {

// An output stream buffer on a file descriptor that remembers the first write error (errno).
class FdStreamBuffer : public std::streambuf {
 public:
  explicit FdStreamBuffer(int fd);
  int error() const { return error_; }
  // Writes out what is buffered; false (and error() set) on failure.
  bool drain();

 protected:
  int_type overflow(int_type ch) override;
  int sync() override { return drain() ? 0 : -1; }

 private:
  int fd_;
  int error_ = 0;
  std::vector<char> buffer_;
};

class OutputFile {
 public:
  // Classifies `path` ("-": standard output) and opens it now, before any frame is tracked.
  // Throws std::runtime_error naming the path (a folder, a missing folder, no permission).
  explicit OutputFile(std::string path);
  // Unless committed: the temporary file is removed (an existing target is left untouched).
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  std::ostream& stream() { return stream_; }
  const std::string& path() const { return target_.path; }
  const OutputTarget& target() const { return target_; }
  // The file written until commit ("" when written in place).
  const std::string& temporary_path() const { return temporary_; }

  // Hands the lines written so far to a live reader (standard output, FIFO, device), so a
  // pipeline sees each frame as it is tracked; nothing for files, which appear on commit.
  void end_record();
  // True once the reader of a pipe has gone (EPIPE): the run should stop as on a signal.
  bool reader_gone() const { return buffer_.error() == EPIPE; }
  // Flushes, syncs and closes. Throws std::runtime_error "PATH: write failed: <reason>" (a
  // pipe whose reader has gone is not a failure: see reader_gone()).
  void finish();
  // Renames the finished temporary file onto the target; nothing for in-place outputs.
  void publish();
  void commit() {
    finish();
    publish();
  }

 private:
  // In this order: each is initialised from the ones before it.
  OutputTarget target_;
  std::string temporary_;
  int fd_;
  FdStreamBuffer buffer_;
  std::ostream stream_;
  bool finished_ = false;
  bool published_ = false;
};

}  // namespace scbt
