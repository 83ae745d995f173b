// Depth images aligned with the colour frames of `scbt track --depth`: a folder of 16-bit PNGs
// numbered like the colour frames (the i-th depth image belongs to the i-th frame), or a TUM
// RGB-D folder (rgb/, depth/, rgb.txt, depth.txt; Sturm et al. 2012) whose colour frames are
// rgb.txt's list and whose depth images are associated with them by timestamp.
#pragma once

#include <opencv2/core/mat.hpp>
#include <string>
#include <utility>
#include <vector>

namespace scbt {

// "timestamp filename" lines of a TUM list file (rgb.txt, depth.txt); '#' starts a comment.
// Throws std::runtime_error naming FILE:LINE for a malformed line, and for a file with no entry.
std::vector<std::pair<double, std::string>> read_tum_list(const std::string& path);

// For each colour entry, the index of the depth entry nearest in time if within max_difference
// seconds, else -1 (TUM's associate.py matches within 0.02 s). Both lists sorted by time.
std::vector<int> associate_by_timestamp(const std::vector<std::pair<double, std::string>>& colour,
                                        const std::vector<std::pair<double, std::string>>& depth,
                                        double max_difference = 0.02);

// True when `folder` holds rgb.txt and depth.txt.
bool is_tum_rgbd_folder(const std::string& folder);

class DepthSource {
 public:
  // Throws std::runtime_error naming the input when it is neither kind of folder.
  explicit DepthSource(const std::string& input);

  // The depth image of frame `index` (0-based) as CV_16UC1; empty when a TUM frame has no depth
  // within 0.02 s or the numbered folder has no image for it. Throws std::runtime_error naming
  // the file when it cannot be read or is not a single-channel 16-bit image.
  cv::Mat read(int index) const;

  int size() const { return static_cast<int>(files_.size()); }
  bool is_tum() const { return tum_; }
  // TUM: the colour frames' files (rgb.txt's order), to be tracked in that order.
  const std::vector<std::string>& colour_files() const { return colour_files_; }

 private:
  bool tum_ = false;
  std::vector<std::string> files_;  // per frame, "" when it has no depth
  std::vector<std::string> colour_files_;
};

}  // namespace scbt
