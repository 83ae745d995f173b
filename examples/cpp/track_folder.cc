// Tracks a boundary through a folder of frames with the installed scbt library and prints the
// boundary of every frame as one line `n x1 y1 ... xn yn` (scbt's polygon format).
//
//   track_folder FRAMES_DIR INIT_POLYGON_FILE
//
// Frames are the folder's images in any format `scbt track` reads (jpg, jpeg, png, bmp, tif,
// tiff, ppm, pgm, webp, in any case), in name order -- all-digit names by their number, so that
// 9.jpg comes before 10.jpg; the first line of INIT_POLYGON_FILE is the boundary in the first
// frame.
#include <scbt/geometry/polygon_io.h>
#include <scbt/tracker/tracker.h>
#include <scbt/version.h>

#include <algorithm>
#include <cctype>
#include <exception>
#include <filesystem>
#include <iostream>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>
#include <string>
#include <vector>

namespace fs = std::filesystem;

bool is_frame(const fs::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const char* known :
       {".jpg", ".jpeg", ".png", ".bmp", ".tif", ".tiff", ".ppm", ".pgm", ".webp"}) {
    if (ext == known) return true;
  }
  return false;
}

bool all_digits(const std::string& s) {
  return !s.empty() &&
         std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
}

// Name order, all-digit names first and by their number.
bool frame_order(const fs::path& a, const fs::path& b) {
  const std::string sa = a.stem().string(), sb = b.stem().string();
  const bool na = all_digits(sa), nb = all_digits(sb);
  if (na != nb) return na;
  if (na) {
    const std::string va = sa.substr(std::min(sa.find_first_not_of('0'), sa.size() - 1));
    const std::string vb = sb.substr(std::min(sb.find_first_not_of('0'), sb.size() - 1));
    if (va.size() != vb.size()) return va.size() < vb.size();
    if (va != vb) return va < vb;
  }
  return a.filename() < b.filename();
}

std::vector<fs::path> frame_paths(const std::string& folder) {
  std::vector<fs::path> paths;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder))
    if (entry.is_regular_file() && is_frame(entry.path())) paths.push_back(entry.path());
  std::sort(paths.begin(), paths.end(), frame_order);
  return paths;
}

cv::Mat read_frame(const fs::path& path) {
  cv::Mat frame = cv::imread(path.string());  // 8-bit BGR, whatever the file holds
  if (frame.empty()) throw std::runtime_error("cannot read " + path.string());
  return frame;
}

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: " << argv[0] << " FRAMES_DIR INIT_POLYGON_FILE  (scbt " SCBT_VERSION ")\n";
    return 2;
  }
  try {
    const std::vector<fs::path> paths = frame_paths(argv[1]);
    if (paths.empty()) throw std::runtime_error(std::string("no image frames in ") + argv[1]);

    scbt::Tracker tracker;  // default options: the paper's settings
    tracker.init(read_frame(paths[0]), scbt::read_first_polygon(argv[2]));
    std::cout << scbt::format_polygon_line(tracker.boundary()) << '\n';
    for (std::size_t i = 1; i < paths.size(); ++i) {
      const scbt::TrackResult result = tracker.track(read_frame(paths[i]));
      std::cout << scbt::format_polygon_line(result.boundary) << '\n';
      std::cerr << "frame " << i + 1 << ": " << scbt::to_string(result.state) << ", confidence "
                << result.confidence << ", " << result.total_ms() << " ms\n";
    }
  } catch (const std::exception& e) {
    std::cerr << "track_folder: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
