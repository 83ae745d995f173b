// Between ROS messages and the tracker's types: polygons, boxes, images and the state report.
#pragma once

#include <geometry_msgs/PolygonStamped.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/RegionOfInterest.h>

#include <opencv2/core/mat.hpp>
#include <string>

#include "scbt/depth/pinhole_camera.h"
#include "scbt/geometry/polygon.h"

namespace scbt::ros_node {

// The boundary as a polygon in pixels (z = 0) stamped with the image's header.
geometry_msgs::PolygonStamped to_polygon_msg(const Polygon& polygon,
                                             const std_msgs::Header& header);

// The polygon's (x, y) vertices; z is ignored.
Polygon from_polygon_msg(const geometry_msgs::Polygon& polygon);

// The region as a box. Throws std::invalid_argument for an empty one.
cv::Rect from_roi_msg(const sensor_msgs::RegionOfInterest& roi);

// True for the encodings the tracker takes: 8-bit mono8, bgr8, rgb8, bgra8 and rgba8.
bool is_tracker_encoding(const std::string& encoding);

// The image as an 8-bit grey, BGR or BGRA matrix sharing the message's pixels where it can (mono8,
// bgr8, bgra8; valid while `image` lives), converted otherwise (rgb8, rgba8). Throws
// std::invalid_argument for any other encoding or a malformed message (cv_bridge's errors rethrown
// with the encoding named).
cv::Mat to_tracker_image(const sensor_msgs::ImageConstPtr& image);

// True for the depth encodings the node takes (REP 118): 16UC1 (millimetres) and 32FC1 (metres).
bool is_depth_encoding(const std::string& encoding);

// The depth image as it is (CV_16UC1 or CV_32FC1, shared with the message: valid while `depth`
// lives). Throws std::invalid_argument for another encoding or a malformed message.
cv::Mat to_depth_image(const sensor_msgs::ImageConstPtr& depth);

// The camera's intrinsics and lens distortion (plumb_bob or rational_polynomial, or none).
// Throws std::invalid_argument for an uncalibrated camera (K all zero), another distortion model,
// binning or a region of interest (not supported).
PinholeIntrinsics from_camera_info_msg(const sensor_msgs::CameraInfo& info);

}  // namespace scbt::ros_node
