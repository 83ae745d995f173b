// What an output path names, decided before anything is written: standard output, a file that
// must be written in place (device, FIFO, socket), or a regular file that is replaced atomically.
#pragma once

#include <sys/types.h>

#include <string>

#include "scbt/io/printable.h"

namespace scbt {

enum class OutputKind {
  kStdout,   // "-": standard output, written as it goes
  kInPlace,  // character/block device, FIFO or socket (or a symlink to one): opened and written,
             // never renamed over
  kReplace,  // regular file, new or existing (or a symlink to one): written to a temporary file
             // in the target's folder and renamed onto the target on commit
};

struct OutputTarget {
  std::string path;    // as the user gave it (used in messages)
  std::string target;  // the file actually written: `path` with symlinks resolved
  OutputKind kind = OutputKind::kReplace;
  bool exists = false;  // the target exists already
  mode_t mode = 0;      // its permission bits, kept by the replacement
  uid_t uid = 0;
  gid_t gid = 0;
};

// Classifies `path` ("-" is standard output). Throws std::runtime_error naming the path when it
// is a folder, its folder does not exist, or it cannot be examined.
OutputTarget classify_output(const std::string& path);

// Creates a new, empty file next to `target` (same folder, so rename() is atomic) named
// ".<name>.tmp-<pid>-<counter><suffix>" with O_EXCL: never an existing file, never shared with
// another process or another output of this one. Returns its open descriptor and sets `*created`.
// Throws std::runtime_error naming `shown_path` on failure.
int create_temporary_sibling(const std::string& target, const std::string& suffix,
                             const std::string& shown_path, std::string* created);

// Gives the temporary file at `fd` the permission bits (and, when allowed, the owner) of the
// target it is going to replace, so an 0600 file stays 0600.
void copy_permissions(int fd, const OutputTarget& target);

}  // namespace scbt
