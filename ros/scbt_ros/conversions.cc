#include "scbt_ros/conversions.h"

#include <cv_bridge/cv_bridge.h>
#include <sensor_msgs/image_encodings.h>

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

Polygon from_roi_msg(const sensor_msgs::RegionOfInterest& roi) {
  return box_polygon(roi.x_offset, roi.y_offset, roi.width, roi.height);
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

cv::Mat to_depth_metres(const sensor_msgs::ImageConstPtr& depth) {
  if (!is_depth_encoding(depth->encoding)) {
    throw std::invalid_argument("depth encoding '" + depth->encoding +
                                "' is not supported: expected 16UC1 (mm) or 32FC1 (m)");
  }
  cv_bridge::CvImageConstPtr shared;
  try {
    shared = cv_bridge::toCvShare(depth, depth->encoding);
  } catch (const cv_bridge::Exception& e) {
    throw std::invalid_argument("depth image (" + depth->encoding + ") is malformed: " + e.what());
  }
  if (depth->encoding == enc::TYPE_32FC1) return shared->image;
  cv::Mat metres;
  shared->image.convertTo(metres, CV_32F, 0.001);  // REP 118: 16UC1 depth is in millimetres
  return metres;
}

}  // namespace scbt::ros_node
