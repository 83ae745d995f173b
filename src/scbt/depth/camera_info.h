// Camera intrinsics from a file: a ROS camera_info YAML (camera_matrix / distortion_coefficients
// with rows, cols, data) or an OpenCV calibration file (camera_matrix or cameraMatrix or K, and
// distortion_coefficients or distCoeffs or D, as !!opencv-matrix), read with cv::FileStorage.
#pragma once

#include <string>

#include "scbt/depth/pinhole_camera.h"

namespace scbt {

// Throws std::runtime_error naming the file and what is missing or malformed.
PinholeIntrinsics read_camera_info(const std::string& path);

}  // namespace scbt
