#include "scbt/testing/avi_test_util.h"

#include <cstdint>
#include <fstream>
#include <iterator>
#include <opencv2/videoio.hpp>

namespace scbt {

std::string write_avi_with_a_dropped_frame(const std::string& path,
                                           const std::vector<cv::Mat>& frames, int dropped) {
  if (frames.empty() || dropped < 1 || dropped > static_cast<int>(frames.size())) {
    return "no such frame to drop";
  }
  {
    cv::VideoWriter writer(path, cv::CAP_FFMPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 10,
                           frames[0].size());
    if (!writer.isOpened()) return "cannot write " + path;
    for (const cv::Mat& frame : frames) writer.write(frame);
  }
  std::ifstream in(path, std::ios::binary);
  std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t movi = data.find("movi");
  const size_t index = data.find("idx1", movi);
  if (movi == std::string::npos || index == std::string::npos) return "unexpected AVI layout";
  std::vector<size_t> chunks;
  for (size_t at = data.find("00dc", movi); at < index; at = data.find("00dc", at + 4)) {
    chunks.push_back(at);
  }
  if (chunks.size() != frames.size()) return "unexpected AVI layout";
  auto put_u32 = [&data](size_t at, uint32_t value) {
    for (int k = 0; k < 4; ++k) data[at + k] = static_cast<char>((value >> (8 * k)) & 0xFF);
  };
  auto get_u32 = [&data](size_t at) {
    uint32_t value = 0;
    for (int k = 0; k < 4; ++k) {
      value |= static_cast<uint32_t>(static_cast<unsigned char>(data[at + k])) << (8 * k);
    }
    return value;
  };
  // The frame's chunk becomes empty; its old payload is hidden in a JUNK chunk after it.
  const size_t chunk = chunks[dropped - 1];
  const uint32_t size = get_u32(chunk + 4);
  put_u32(chunk + 4, 0);
  data.replace(chunk + 8, 4, "JUNK");
  put_u32(chunk + 12, size - 8);
  // Its idx1 entry (offsets count from "movi" in files OpenCV writes) says size 0 as well.
  for (size_t entry = index + 8; entry + 16 <= data.size(); entry += 16) {
    const uint32_t offset = get_u32(entry + 8);
    if (movi + offset == chunk || offset == chunk) put_u32(entry + 12, 0);
  }
  std::ofstream(path, std::ios::binary | std::ios::trunc) << data;
  return "";
}

}  // namespace scbt
