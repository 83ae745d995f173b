#include "scbt/depth/camera_info.h"

#include <opencv2/core.hpp>
#include <stdexcept>

#include "scbt/io/bounded_read.h"
#include "scbt/io/printable.h"

namespace scbt {
namespace {

// The numbers of a matrix node in any of the accepted spellings: !!opencv-matrix, a map with a
// `data` sequence (ROS), or a plain sequence.
std::vector<double> matrix_values(const cv::FileNode& node) {
  std::vector<double> values;
  if (node.isMap() && !node["data"].empty() && node["data"].isSeq()) {
    const cv::FileNode data = node["data"];
    if (node["dt"].empty()) {
      for (const cv::FileNode& item : data) values.push_back(static_cast<double>(item));
      return values;
    }
    cv::Mat matrix;
    node >> matrix;
    matrix.convertTo(matrix, CV_64F);
    return std::vector<double>(matrix.begin<double>(), matrix.end<double>());
  }
  if (node.isSeq())
    for (const cv::FileNode& item : node) values.push_back(static_cast<double>(item));
  return values;
}

cv::FileNode first_present(const cv::FileStorage& storage, std::initializer_list<const char*> keys,
                           std::string* found) {
  for (const char* key : keys) {
    const cv::FileNode node = storage[key];
    if (!node.empty() && !node.isNone()) {
      *found = key;
      return node;
    }
  }
  return cv::FileNode();
}

}  // namespace

PinholeIntrinsics read_camera_info(const std::string& path) { return read_camera_info(path, {}); }

PinholeIntrinsics read_camera_info(const std::string& path,
                                   const std::function<void()>& check_interrupt) {
  // Bounded and interruptible: the file may be endless (/dev/zero) or a FIFO.
  std::string text =
      read_file_bounded(path, {kMaxCameraInfoBytes, "a camera info file"}, check_interrupt);
  const std::string shown = printable(path);
  // ROS writes YAML without the "%YAML:1.0" line OpenCV's parser needs to recognise it.
  const std::size_t start = text.find_first_not_of(" \t\r\n");
  if (start != std::string::npos && text[start] != '%' && text[start] != '<' && text[start] != '{')
    text = "%YAML:1.0\n---\n" + text;
  cv::FileStorage storage;
  try {
    storage.open(text, cv::FileStorage::READ | cv::FileStorage::MEMORY);
  } catch (const cv::Exception& e) {
    throw std::runtime_error(shown + ": not a YAML/XML/JSON camera info file (" + e.msg + ")");
  }
  if (!storage.isOpened())
    throw std::runtime_error(shown + ": not a YAML/XML/JSON camera info file");
  const cv::FileNode model = storage["distortion_model"];
  if (model.isString()) {
    const std::string name = model.string();
    if (name != "plumb_bob" && name != "rational_polynomial")
      throw std::runtime_error(shown + ": distortion_model '" + printable(name) +
                               "' is not supported (plumb_bob or rational_polynomial)");
  }
  std::string key;
  const cv::FileNode k_node =
      first_present(storage, {"camera_matrix", "cameraMatrix", "K", "k"}, &key);
  if (k_node.empty())
    throw std::runtime_error(shown + ": no camera_matrix (or cameraMatrix, K) entry");
  const std::vector<double> k = matrix_values(k_node);
  if (k.size() != 9)
    throw std::runtime_error(shown + ": " + key + " must hold 9 numbers (3x3), got " +
                             std::to_string(k.size()));
  PinholeIntrinsics camera;
  camera.fx = k[0];
  camera.cx = k[2];
  camera.fy = k[4];
  camera.cy = k[5];
  const cv::FileNode d_node = first_present(
      storage, {"distortion_coefficients", "distCoeffs", "dist_coeffs", "D", "d"}, &key);
  if (!d_node.empty()) camera.distortion = matrix_values(d_node);
  try {
    camera.check();
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(shown + ": " + e.what());
  }
  return camera;
}

}  // namespace scbt
