// Camera intrinsics from a file: a ROS camera_info YAML (camera_matrix / distortion_coefficients
// with rows, cols, data) or an OpenCV calibration file (camera_matrix or cameraMatrix or K, and
// distortion_coefficients or distCoeffs or D, as !!opencv-matrix), read with cv::FileStorage.
#pragma once

#include <functional>
#include <string>

#include "scbt/depth/pinhole_camera.h"

namespace scbt {

// Throws std::runtime_error naming the file and what is missing or malformed. The file is read
// with a limit of 1 MiB, checked while reading (it may be endless, /dev/zero, or a FIFO), and the
// read stops with scbt::Interrupted (scbt/io/bounded_read.h) when a stop signal arrives.
PinholeIntrinsics read_camera_info(const std::string& path);
// The same, calling `check_interrupt` before each read and whenever a system call is interrupted
// by a signal (EINTR); it may throw to abandon the read (Python: a pending KeyboardInterrupt).
PinholeIntrinsics read_camera_info(const std::string& path,
                                   const std::function<void()>& check_interrupt);

}  // namespace scbt
