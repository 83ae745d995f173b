#include "scbt/eval/dataset.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <stdexcept>

namespace scbt {
namespace fs = std::filesystem;
namespace {

constexpr const char* kFramesFolder = "OriginalVideosAVI";
constexpr const char* kTruthFolder = "GroundTruthByPolygons";
constexpr const char* kTruthSuffix = "_TrackingGroundTruth.txt";

bool is_video_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".avi" || ext == ".mp4" || ext == ".mov" || ext == ".mkv";
}

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

}  // namespace

std::vector<DatasetSequence> list_dataset_sequences(const std::string& root) {
  std::error_code ec;
  if (!fs::is_directory(root, ec)) {
    throw std::runtime_error("dataset '" + root + "' is not a directory");
  }
  const fs::path frames_root = fs::path(root) / kFramesFolder;
  const fs::path truth_root = fs::path(root) / kTruthFolder;
  if (!fs::is_directory(frames_root, ec) || !fs::is_directory(truth_root, ec)) {
    throw std::runtime_error("dataset '" + root + "' lacks " + kFramesFolder + "/ or " +
                             kTruthFolder + "/ (expected " + kFramesFolder +
                             "/<Seq>/NNNN.jpg and " + kTruthFolder + "/<Seq>" + kTruthSuffix + ")");
  }
  // Frames: a folder per sequence, or a video file per sequence when no folder has that name.
  std::map<std::string, std::string> frames;
  for (const fs::directory_entry& entry : fs::directory_iterator(frames_root)) {
    if (entry.is_directory()) frames[entry.path().filename().string()] = entry.path().string();
  }
  for (const fs::directory_entry& entry : fs::directory_iterator(frames_root)) {
    if (entry.is_regular_file() && is_video_extension(entry.path())) {
      frames.emplace(entry.path().stem().string(), entry.path().string());
    }
  }
  std::vector<DatasetSequence> sequences;
  const std::string suffix = kTruthSuffix;
  for (const fs::directory_entry& entry : fs::directory_iterator(truth_root)) {
    const std::string file = entry.path().filename().string();
    if (!entry.is_regular_file() || file.size() <= suffix.size() ||
        file.compare(file.size() - suffix.size(), suffix.size(), suffix) != 0) {
      continue;
    }
    const std::string name = file.substr(0, file.size() - suffix.size());
    const auto found = frames.find(name);
    if (found == frames.end()) continue;
    sequences.push_back({name, found->second, entry.path().string()});
  }
  if (sequences.empty()) {
    throw std::runtime_error("dataset '" + root + "' has no sequence with both " + kFramesFolder +
                             "/<Seq> and " + kTruthFolder + "/<Seq>" + kTruthSuffix);
  }
  std::sort(sequences.begin(), sequences.end(),
            [](const DatasetSequence& a, const DatasetSequence& b) { return a.name < b.name; });
  return sequences;
}

std::vector<DatasetSequence> select_dataset_sequences(const std::string& root,
                                                      const std::vector<std::string>& names) {
  std::vector<DatasetSequence> all = list_dataset_sequences(root);
  if (names.empty()) return all;
  std::vector<std::string> known;
  for (const DatasetSequence& s : all) known.push_back(s.name);
  std::vector<DatasetSequence> selected;
  std::set<std::string> seen;
  for (const std::string& name : names) {
    if (!seen.insert(name).second) {
      throw std::invalid_argument("sequence '" + name + "' given twice");
    }
    const auto found = std::find_if(all.begin(), all.end(),
                                    [&](const DatasetSequence& s) { return s.name == name; });
    if (found == all.end()) {
      throw std::invalid_argument("unknown sequence '" + name + "' (dataset has: " + join(known) +
                                  ")");
    }
    selected.push_back(*found);
  }
  return selected;
}

std::string results_path(const std::string& results_dir, const std::string& name) {
  return (fs::path(results_dir) / (name + ".txt")).string();
}

}  // namespace scbt
