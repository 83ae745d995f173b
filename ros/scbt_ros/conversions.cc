#include "scbt_ros/conversions.h"

#include <cv_bridge/cv_bridge.h>
#include <sensor_msgs/image_encodings.h>

#include <algorithm>
#include <stdexcept>

#include "scbt_ros/node_options.h"

namespace scbt::ros_node {

namespace enc = sensor_msgs::image_encodings;

geometry_msgs::PolygonStamped to_polygon_msg(const Polygon& polygon,
                                             const std_msgs::Header& header) {
  geometry_msgs::PolygonStamped msg;
  msg.header = header;
  msg.polygon.points.reserve(polygon.size());
  for (const Point& p : polygon) {
    geometry_msgs::Point32 q;
    q.x = static_cast<float>(p.x);
    q.y = static_cast<float>(p.y);
    q.z = 0.0f;
    msg.polygon.points.push_back(q);
  }
  return msg;
}

Polygon from_polygon_msg(const geometry_msgs::Polygon& polygon) {
  Polygon out;
  out.reserve(polygon.points.size());
  for (const auto& p : polygon.points) out.emplace_back(p.x, p.y);
  return out;
}

cv::Rect from_roi_msg(const sensor_msgs::RegionOfInterest& roi) {
  return pixel_box(roi.x_offset, roi.y_offset, roi.width, roi.height);
}

bool is_tracker_encoding(const std::string& encoding) {
  return encoding == enc::MONO8 || encoding == enc::BGR8 || encoding == enc::RGB8 ||
         encoding == enc::BGRA8 || encoding == enc::RGBA8;
}

cv::Mat to_tracker_image(const sensor_msgs::ImageConstPtr& image) {
  if (!is_tracker_encoding(image->encoding)) {
    throw std::invalid_argument("image encoding '" + image->encoding +
                                "' is not supported: expected mono8, bgr8, rgb8, bgra8 or rgba8");
  }
  try {
    // rgb8/rgba8 are converted to BGR; the others are shared as they are.
    const bool rgb = image->encoding == enc::RGB8 || image->encoding == enc::RGBA8;
    return cv_bridge::toCvShare(image, rgb ? enc::BGR8 : image->encoding)->image;
  } catch (const cv_bridge::Exception& e) {
    throw std::invalid_argument("image (" + image->encoding + ", " + std::to_string(image->width) +
                                "x" + std::to_string(image->height) +
                                ") is malformed: " + e.what());
  }
}

bool is_depth_encoding(const std::string& encoding) {
  return encoding == enc::TYPE_16UC1 || encoding == enc::TYPE_32FC1;
}

cv::Mat to_depth_image(const sensor_msgs::ImageConstPtr& depth) {
  if (!is_depth_encoding(depth->encoding)) {
    throw std::invalid_argument("depth encoding '" + depth->encoding +
                                "' is not supported: expected 16UC1 (mm) or 32FC1 (m)");
  }
  try {
    return cv_bridge::toCvShare(depth, depth->encoding)->image;
  } catch (const cv_bridge::Exception& e) {
    throw std::invalid_argument("depth image (" + depth->encoding + ") is malformed: " + e.what());
  }
}

PinholeIntrinsics from_camera_info_msg(const sensor_msgs::CameraInfo& info) {
  if (info.K[0] == 0.0 || info.K[4] == 0.0) {
    throw std::invalid_argument("camera_info has no intrinsics (K is zero): camera not calibrated");
  }
  if (info.binning_x > 1 || info.binning_y > 1 || info.roi.width != 0 || info.roi.height != 0) {
    throw std::invalid_argument(
        "camera_info with binning or a region of interest is not supported");
  }
  PinholeIntrinsics camera;
  camera.fx = info.K[0];
  camera.fy = info.K[4];
  camera.cx = info.K[2];
  camera.cy = info.K[5];
  const bool zero = std::all_of(info.D.begin(), info.D.end(), [](double d) { return d == 0.0; });
  if (!zero) {
    if (info.distortion_model != "plumb_bob" && info.distortion_model != "rational_polynomial") {
      throw std::invalid_argument("camera_info distortion model '" + info.distortion_model +
                                  "' is not supported: expected plumb_bob or rational_polynomial");
    }
    camera.distortion = info.D;
  }
  camera.check();
  return camera;
}

}  // namespace scbt::ros_node
