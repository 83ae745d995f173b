#include "scbt/io/output_target.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace scbt {
namespace fs = std::filesystem;
namespace {

std::runtime_error error_for(const std::string& shown, const std::string& what) {
  return std::runtime_error(printable(shown) + ": " + what);
}

// Follows `path` through symlinks (relative ones from the link's folder) to the name of the file
// they lead to, which need not exist. Up to 40 links, as the kernel allows.
std::string resolve_symlinks(const std::string& path) {
  fs::path current(path);
  for (int depth = 0; depth < 40; ++depth) {
    struct stat info {};
    if (::lstat(current.c_str(), &info) != 0 || !S_ISLNK(info.st_mode)) return current.string();
    std::error_code error;
    const fs::path link = fs::read_symlink(current, error);
    if (error) throw error_for(path, "cannot read the symbolic link: " + error.message());
    current = link.is_absolute() ? link : current.parent_path() / link;
  }
  throw error_for(path, "too many levels of symbolic links");
}

}  // namespace

OutputTarget classify_output(const std::string& path) {
  OutputTarget out;
  out.path = path;
  if (path == "-") {
    out.kind = OutputKind::kStdout;
    out.target = path;
    return out;
  }
  if (path.empty()) throw std::invalid_argument("an output path is empty");
  out.target = resolve_symlinks(path);
  struct stat info {};
  if (::stat(out.target.c_str(), &info) == 0) {
    out.exists = true;
    if (S_ISDIR(info.st_mode)) throw error_for(path, "is a folder, not a file");
    out.kind = S_ISREG(info.st_mode) ? OutputKind::kReplace : OutputKind::kInPlace;
    out.mode = info.st_mode & 07777;
    out.uid = info.st_uid;
    out.gid = info.st_gid;
    return out;
  }
  if (errno != ENOENT)
    throw error_for(path, std::string("cannot examine: ") + std::strerror(errno));
  const fs::path parent = fs::path(out.target).parent_path();
  struct stat folder {};
  if (::stat(parent.empty() ? "." : parent.c_str(), &folder) != 0 || !S_ISDIR(folder.st_mode)) {
    throw error_for(path, "cannot open for writing: its folder does not exist");
  }
  out.kind = OutputKind::kReplace;
  return out;
}

int create_temporary_sibling(const std::string& target, const std::string& suffix,
                             const std::string& shown_path, std::string* created) {
  static std::atomic<unsigned> counter{0};
  const fs::path where(target);
  const std::string stem = "." + where.filename().string() + ".tmp-" + std::to_string(::getpid());
  for (int attempt = 0; attempt < 100; ++attempt) {
    const fs::path name = where.parent_path() / (stem + "-" + std::to_string(counter++) + suffix);
    const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      *created = name.string();
      return fd;
    }
    if (errno != EEXIST) {
      throw error_for(shown_path, std::string("cannot open for writing: ") + std::strerror(errno));
    }
  }
  throw error_for(shown_path, "cannot open for writing: no free temporary name");
}

void copy_permissions(int fd, const OutputTarget& target) {
  if (!target.exists) return;  // a new file gets 0666 minus the umask, as any other
  // Only root may give a file away; anyone else's replacement is theirs, as with any editor.
  // The owner first: a change of owner clears set-id bits, which fchmod then restores.
  if (::geteuid() == 0) (void)!::fchown(fd, target.uid, target.gid);
  if (::fchmod(fd, target.mode) != 0) {
    throw error_for(target.path,
                    std::string("cannot keep its permissions: ") + std::strerror(errno));
  }
}

}  // namespace scbt
