// Tracks a boundary through a folder of frames with the installed scbt library and prints the
// boundary of every frame as one line `n x1 y1 ... xn yn` (scbt's polygon format).
//
//   track_folder FRAMES_DIR INIT_POLYGON_FILE
//
// Frames are the folder's images in name order; the first line of INIT_POLYGON_FILE is the
// boundary in the first frame.
#include <scbt/geometry/polygon_io.h>
#include <scbt/tracker/tracker.h>
#include <scbt/version.h>

#include <exception>
#include <iostream>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: " << argv[0] << " FRAMES_DIR INIT_POLYGON_FILE  (scbt " SCBT_VERSION ")\n";
    return 2;
  }
  try {
    std::vector<cv::String> paths;
    cv::glob(std::string(argv[1]) + "/*.png", paths);  // sorted by name
    if (paths.empty()) throw std::runtime_error(std::string("no .png frames in ") + argv[1]);

    scbt::Tracker tracker;  // default options: the paper's settings
    tracker.init(cv::imread(paths[0]), scbt::read_first_polygon(argv[2]));
    std::cout << scbt::format_polygon_line(tracker.boundary()) << '\n';
    for (std::size_t i = 1; i < paths.size(); ++i) {
      const cv::Mat frame = cv::imread(paths[i]);
      if (frame.empty()) throw std::runtime_error("cannot read " + paths[i]);
      const scbt::TrackResult result = tracker.track(frame);
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
