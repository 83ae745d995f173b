// Tracks one dataset sequence from its first ground-truth polygon with default options, all frames
// decoded before the first track() call, and prints the frame count and a checksum of every
// boundary: the workload of bench/compare_instructions.sh, which counts the instructions spent in
// Tracker::track under valgrind (a count that does not drift with the machine's load, as wall time
// does). It uses only Tracker's init/track API and links no video I/O (the video stack's libhwy
// stops valgrind with an instruction it cannot decode), so that the same file builds against an
// older checkout for a comparison.
//
//   build/bench/scbt_track_frames DATASET_DIR SEQUENCE [MAX_FRAMES]
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "scbt/tracker/tracker.h"

namespace {

// The first line of the ground truth, `n x1 y1 ... xn yn`.
bool read_first_polygon(const std::string& path, scbt::Polygon* polygon) {
  std::ifstream file(path);
  std::string line;
  if (!std::getline(file, line)) return false;
  std::istringstream in(line);
  int n = 0;
  if (!(in >> n) || n < 3) return false;
  for (int i = 0; i < n; ++i) {
    double x = 0.0, y = 0.0;
    if (!(in >> x >> y)) return false;
    polygon->emplace_back(x, y);
  }
  return true;
}

// FNV-1a over the boundary's coordinates: equal output, equal checksum.
void mix(const scbt::Polygon& polygon, std::uint64_t* hash) {
  for (const scbt::Point& p : polygon) {
    for (double v : {p.x, p.y}) {
      unsigned char bytes[sizeof v];
      std::memcpy(bytes, &v, sizeof v);
      for (unsigned char b : bytes) *hash = (*hash ^ b) * 1099511628211ULL;
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3 || argc > 4) {
    std::fprintf(stderr, "usage: %s DATASET_DIR SEQUENCE [MAX_FRAMES]\n", argv[0]);
    return 2;
  }
  const std::string dataset = argv[1], sequence = argv[2];
  const int max_frames = argc == 4 ? std::atoi(argv[3]) : 0;
  scbt::Polygon initial;
  const std::string truth =
      dataset + "/GroundTruthByPolygons/" + sequence + "_TrackingGroundTruth.txt";
  if (!read_first_polygon(truth, &initial)) {
    std::fprintf(stderr, "%s: no polygon on the first line of %s\n", argv[0], truth.c_str());
    return 1;
  }
  std::vector<cv::Mat> frames;
  for (int k = 1; max_frames <= 0 || k <= max_frames; ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "/%04d.jpg", k);
    cv::Mat frame = cv::imread(dataset + "/OriginalVideosAVI/" + sequence + name);
    if (frame.empty()) break;
    frames.push_back(frame);
  }
  if (frames.size() < 2) {
    std::fprintf(stderr, "%s: fewer than two frames of %s in %s\n", argv[0], sequence.c_str(),
                 dataset.c_str());
    return 1;
  }
  scbt::Tracker tracker;
  tracker.init(frames[0], initial);
  std::uint64_t hash = 14695981039346656037ULL;
  for (size_t i = 1; i < frames.size(); ++i) mix(tracker.track(frames[i]).boundary, &hash);
  std::printf("%s frames %zu checksum %016llx\n", sequence.c_str(), frames.size() - 1,
              static_cast<unsigned long long>(hash));
  return 0;
}
