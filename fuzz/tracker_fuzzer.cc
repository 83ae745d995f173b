// libFuzzer target: the tracker fed a random small frame pair and a random initial polygon.
// Layout of the input: width, height (1 byte each, 8..71 px), channels selector, vertex count
// (3..10), 2 bytes per vertex, then pixel bytes for two frames (cycled when short). Invalid
// polygons must be refused with std::invalid_argument; valid ones must track without crashing
// and yield a finite boundary.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <opencv2/core.hpp>
#include <stdexcept>

#include "scbt/tracker/tracker.h"

namespace {

class Bytes {
 public:
  Bytes(const uint8_t* data, size_t size) : data_(data), size_(size) {}
  uint8_t next() { return size_ == 0 ? 0 : data_[at_++ % size_]; }
  size_t left() const { return at_ < size_ ? size_ - at_ : 0; }

 private:
  const uint8_t* data_;
  size_t size_;
  size_t at_ = 0;
};

cv::Mat make_frame(Bytes* bytes, int width, int height, int channels) {
  cv::Mat frame(height, width, CV_8UC(channels));
  // Pixels come in runs so that edges (and line segments) appear, not only noise.
  for (int y = 0; y < height; ++y) {
    uchar* row = frame.ptr<uchar>(y);
    uchar value = bytes->next();
    for (int x = 0; x < width * channels; ++x) {
      if ((x + y) % 7 == 0) value = bytes->next();
      row[x] = value;
    }
  }
  return frame;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 8) return 0;
  Bytes bytes(data, size);
  const int width = 8 + bytes.next() % 64;
  const int height = 8 + bytes.next() % 64;
  const int channel_choice[3] = {1, 3, 4};
  const int channels = channel_choice[bytes.next() % 3];
  const int vertices = 3 + bytes.next() % 8;
  scbt::Polygon polygon;
  for (int i = 0; i < vertices; ++i) {
    // Coordinates may fall outside the frame (up to 1.25x) to exercise the refusal.
    const double x = bytes.next() / 255.0 * width * 1.25 - width * 0.1;
    const double y = bytes.next() / 255.0 * height * 1.25 - height * 0.1;
    polygon.emplace_back(x, y);
  }
  const cv::Mat first = make_frame(&bytes, width, height, channels);
  const cv::Mat second = make_frame(&bytes, width, height, channels);

  scbt::TrackerOptions options;
  options.max_segments = 50;
  scbt::Tracker tracker(options);
  try {
    tracker.init(first, polygon);
  } catch (const std::invalid_argument&) {
    return 0;
  }
  for (const cv::Mat* frame : {&second, &first}) {
    const scbt::TrackResult result = tracker.track(*frame);
    for (const scbt::Point& p : result.boundary) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) std::abort();
    }
    if (result.num_kept > options.max_segments) std::abort();
  }
  return 0;
}
