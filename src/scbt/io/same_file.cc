#include "scbt/io/same_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>

#include "scbt/io/output_target.h"

namespace scbt {
namespace fs = std::filesystem;
namespace {

// What a path names: its inode when it exists, and its absolute name with symlinks resolved.
struct Identity {
  bool exists = false;
  bool is_folder = false;
  bool is_char_device = false;
  dev_t device = 0;
  ino_t inode = 0;
  std::string resolved;
};

Identity identify(const std::string& path) {
  Identity id;
  struct stat info {};
  const bool found =
      path == "-" ? ::fstat(STDOUT_FILENO, &info) == 0 : ::stat(path.c_str(), &info) == 0;
  if (found) {
    id.exists = true;
    id.is_folder = S_ISDIR(info.st_mode);
    id.is_char_device = S_ISCHR(info.st_mode);
    id.device = info.st_dev;
    id.inode = info.st_ino;
  }
  if (path == "-") {
    id.resolved = "-";
    return id;
  }
  std::error_code error;
  const fs::path resolved = fs::weakly_canonical(path, error);
  id.resolved = error ? fs::absolute(path).lexically_normal().string() : resolved.string();
  return id;
}

bool same(const Identity& a, const Identity& b) {
  if (a.exists && b.exists) return a.device == b.device && a.inode == b.inode;
  return a.resolved == b.resolved;
}

Identity parent_of(const std::string& path) {
  if (path == "-") return {};
  const std::string resolved = identify(path).resolved;
  const fs::path parent = fs::path(resolved).parent_path();
  return identify(parent.empty() ? "." : parent.string());
}

bool named_like_a_frame(const std::string& path) {
  const fs::path name = fs::path(path).filename();
  const std::string stem = name.stem().string();
  return name.extension() == ".jpg" && !stem.empty() &&
         std::all_of(stem.begin(), stem.end(), [](unsigned char c) { return std::isdigit(c); });
}

[[noreturn]] void refuse(const NamedPath& output, const std::string& relation,
                         const NamedPath& other) {
  throw std::invalid_argument(output.option + " " + printable(output.path) + " " + relation + " " +
                              other.option + " " + printable(other.path) +
                              "; refusing to overwrite it");
}

}  // namespace

void check_no_overwrite(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs,
                        const std::vector<NamedPath>& output_folders) {
  std::vector<Identity> input_ids;
  for (const NamedPath& input : inputs) input_ids.push_back(identify(input.path));
  std::vector<Identity> output_ids;
  for (const NamedPath& output : outputs) output_ids.push_back(identify(output.path));

  for (size_t o = 0; o < outputs.size(); ++o) {
    const Identity& out = output_ids[o];
    for (size_t i = 0; i < inputs.size(); ++i) {
      const Identity& in = input_ids[i];
      if (!in.exists) continue;  // a camera index, or an input that will fail by itself
      if (in.is_folder && same(parent_of(outputs[o].path), in)) {
        refuse(outputs[o], "is inside the input folder", inputs[i]);
      }
      if (!out.is_char_device && same(out, in)) {
        refuse(outputs[o], "is the same file as", inputs[i]);
      }
    }
    for (size_t p = 0; p < o; ++p) {
      const bool both_stdout = outputs[o].path == "-" && outputs[p].path == "-";
      if (both_stdout || (!out.is_char_device && same(out, output_ids[p]))) {
        refuse(outputs[o], "is the same file as", outputs[p]);
      }
    }
  }
  for (const NamedPath& folder : output_folders) {
    const Identity id = identify(folder.path);
    for (size_t i = 0; i < inputs.size(); ++i) {
      if (input_ids[i].exists && same(id, input_ids[i])) {
        refuse(folder, "is the same folder as", inputs[i]);
      }
    }
    auto clashes = [&](const NamedPath& file) {
      return named_like_a_frame(file.path) && same(parent_of(file.path), id);
    };
    for (const NamedPath& input : inputs) {
      if (clashes(input)) refuse(folder, "would overwrite", input);
    }
    for (const NamedPath& output : outputs) {
      if (clashes(output)) refuse(folder, "would overwrite", output);
    }
  }
}

}  // namespace scbt
