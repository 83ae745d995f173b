#include "scbt/io/depth_source.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <stdexcept>

#include "scbt/geometry/polygon_io.h"
#include "scbt/io/bounded_read.h"
#include "scbt/io/frame_source.h"

namespace scbt {
namespace fs = std::filesystem;
namespace {

// "1 channel of 32-bit float", "3 channels of 8-bit unsigned".
std::string describe_pixel_type(const cv::Mat& image) {
  static const char* const kDepths[] = {"8-bit unsigned", "8-bit signed",  "16-bit unsigned",
                                        "16-bit signed",  "32-bit signed", "32-bit float",
                                        "64-bit float",   "16-bit float"};
  const int depth = image.depth();
  const std::string kind = depth >= 0 && depth < 8 ? kDepths[depth] : "unknown";
  return std::to_string(image.channels()) +
         (image.channels() == 1 ? " channel of " : " channels of ") + kind;
}

}  // namespace

std::vector<std::pair<double, std::string>> read_tum_list(const std::string& path) {
  const std::vector<std::string> lines = read_text_lines(path, kMaxTextFileBytes, "a TUM list");
  std::vector<std::pair<double, std::string>> entries;
  for (std::size_t index = 0; index < lines.size(); ++index) {
    const std::string& line = lines[index];
    const std::size_t number = index + 1;
    const std::size_t start = line.find_first_not_of(" \t\r");
    if (start == std::string::npos || line[start] == '#') continue;
    std::istringstream fields(line);
    double time = 0.0;
    std::string name;
    if (!(fields >> time >> name) || !std::isfinite(time))
      throw std::runtime_error(path + ":" + std::to_string(number) +
                               ": expected 'timestamp filename'");
    entries.emplace_back(time, name);
  }
  if (entries.empty()) throw std::runtime_error(path + ": no entries");
  std::stable_sort(entries.begin(), entries.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  return entries;
}

std::vector<int> associate_by_timestamp(const std::vector<std::pair<double, std::string>>& colour,
                                        const std::vector<std::pair<double, std::string>>& depth,
                                        double max_difference) {
  std::vector<int> match(colour.size(), -1);
  for (std::size_t i = 0; i < colour.size(); ++i) {
    const auto after = std::lower_bound(
        depth.begin(), depth.end(), colour[i].first,
        [](const std::pair<double, std::string>& entry, double t) { return entry.first < t; });
    double best = max_difference;
    for (auto it : {after, after == depth.begin() ? depth.end() : after - 1}) {
      if (it == depth.end()) continue;
      const double difference = std::abs(it->first - colour[i].first);
      if (difference <= best) {
        best = difference;
        match[i] = static_cast<int>(it - depth.begin());
      }
    }
  }
  return match;
}

bool is_tum_rgbd_folder(const std::string& folder) {
  std::error_code error;
  return fs::is_regular_file(fs::path(folder) / "rgb.txt", error) &&
         fs::is_regular_file(fs::path(folder) / "depth.txt", error);
}

DepthSource::DepthSource(const std::string& input) {
  std::error_code error;
  if (!fs::is_directory(input, error))
    throw std::runtime_error(input +
                             ": depth input must be a folder of numbered 16-bit PNGs or a "
                             "TUM RGB-D folder (rgb.txt, depth.txt)");
  if (!is_tum_rgbd_folder(input)) {
    files_ = list_numbered_images(input);
    return;
  }
  tum_ = true;
  const fs::path root(input);
  const auto colour = read_tum_list((root / "rgb.txt").string());
  const auto depth = read_tum_list((root / "depth.txt").string());
  const std::vector<int> match = associate_by_timestamp(colour, depth);
  for (std::size_t i = 0; i < colour.size(); ++i) {
    colour_files_.push_back((root / colour[i].second).string());
    files_.push_back(match[i] < 0 ? std::string() : (root / depth[match[i]].second).string());
  }
}

cv::Mat DepthSource::read(int index) const {
  if (index < 0 || index >= size() || files_[index].empty()) return cv::Mat();
  const std::string& path = files_[index];
  const std::string bytes = read_file_bounded(path, {kMaxImageFileBytes, "a depth image"});
  cv::Mat depth;
  if (!bytes.empty()) {
    const cv::Mat encoded(1, static_cast<int>(bytes.size()), CV_8U,
                          const_cast<char*>(bytes.data()));
    depth = cv::imdecode(encoded, cv::IMREAD_ANYDEPTH | cv::IMREAD_UNCHANGED);
  }
  if (depth.empty()) throw std::runtime_error(path + ": cannot read the depth image");
  if (depth.type() != CV_16UC1)
    throw std::runtime_error(path +
                             ": a depth image must be single-channel 16-bit unsigned (depth "
                             "units, --depth-scale metres each), got " +
                             describe_pixel_type(depth));
  return depth;
}

}  // namespace scbt
