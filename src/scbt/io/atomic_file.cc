#include "scbt/io/atomic_file.h"

#include <unistd.h>

#include <cstdio>
#include <stdexcept>

namespace scbt {

AtomicFile::AtomicFile(std::string path)
    : path_(std::move(path)), temporary_path_(path_ + ".tmp-" + std::to_string(::getpid())) {
  stream_.open(temporary_path_, std::ios::out | std::ios::trunc);
  if (!stream_) throw std::runtime_error(path_ + ": cannot open for writing");
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    stream_.close();
    std::remove(temporary_path_.c_str());
  }
}

void AtomicFile::commit() {
  stream_.flush();
  const bool ok = static_cast<bool>(stream_);
  stream_.close();
  if (!ok) throw std::runtime_error(path_ + ": write failed");
  if (std::rename(temporary_path_.c_str(), path_.c_str()) != 0) {
    throw std::runtime_error(path_ + ": cannot move the finished file into place");
  }
  committed_ = true;
}

}  // namespace scbt
