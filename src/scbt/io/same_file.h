// Refusing, before anything is read or written, a run whose outputs would overwrite its own
// inputs or each other (`--init GT.txt -o GT.txt`, `-o seq/0001.jpg`, `--csv x -o x`, ...).
#pragma once

#include <string>
#include <vector>

namespace scbt {

struct NamedPath {
  std::string option;  // how the user gave it: "INPUT", "--init", "-o", "--csv", ...
  std::string path;
};

// Throws std::invalid_argument naming both paths when an output file is the same file as an
// input or as another output (same device and inode, or the same path once symlinks are
// resolved; "-" is standard output), lies directly inside an input folder, or when an output
// folder is an input folder or would overwrite an input or output named like its frames
// (NNNN.jpg). Inputs that are no file (a camera index) are skipped; character devices
// (/dev/null, a terminal) may appear more than once.
void check_no_overwrite(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs,
                        const std::vector<NamedPath>& output_folders);

}  // namespace scbt
