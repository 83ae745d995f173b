// Output files that appear only when complete: written to a temporary sibling and renamed on
// commit(), so a failed or interrupted run never leaves a partial file or clobbers an old one.
#pragma once

#include <fstream>
#include <string>

namespace scbt {

class AtomicFile {
 public:
  // Opens `path`.tmp-<pid> for writing. Throws std::runtime_error naming the path on failure.
  explicit AtomicFile(std::string path);
  // Removes the temporary file unless commit() succeeded.
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ofstream& stream() { return stream_; }
  const std::string& path() const { return path_; }
  const std::string& temporary_path() const { return temporary_path_; }
  // Flushes, closes and renames onto the final path. Throws std::runtime_error on failure.
  void commit();

 private:
  std::string path_;
  std::string temporary_path_;
  std::ofstream stream_;
  bool committed_ = false;
};

}  // namespace scbt
