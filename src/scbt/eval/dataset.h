// The layout of the public salient closed boundary tracking dataset:
//   DIR/OriginalVideosAVI/<Seq>/0001.jpg ...            (or DIR/OriginalVideosAVI/<Seq>.avi)
//   DIR/GroundTruthByPolygons/<Seq>_TrackingGroundTruth.txt   (line k = frame k)
#pragma once

#include <string>
#include <vector>

namespace scbt {

struct DatasetSequence {
  std::string name;          // e.g. "Bowl"
  std::string frames;        // image folder or video file, for open_frame_source
  std::string ground_truth;  // polygon file, one line per frame
};

// The sequences of `root` that have both frames and a ground-truth file, sorted by name.
// Throws std::runtime_error with a one-line message when `root` is not laid out as the dataset.
std::vector<DatasetSequence> list_dataset_sequences(const std::string& root);

// The named sequences in the given order (all of them when `names` is empty). Throws
// std::invalid_argument naming an unknown or repeated sequence and listing the known ones.
std::vector<DatasetSequence> select_dataset_sequences(const std::string& root,
                                                      const std::vector<std::string>& names);

// Where a tool's results for sequence `name` live inside a results folder: DIR/<name>.txt.
std::string results_path(const std::string& results_dir, const std::string& name);

}  // namespace scbt
