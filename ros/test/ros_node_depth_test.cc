// scbt_node with depth: a rendered clip and a depth stream of the same scene (the object a flat
// tilted plate 0.9-1.1 m away in front of a wall), image, depth and camera_info stamped alike.
// Every ~centroid and ~normal is checked against the plate's true rim in 3-D.
#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/Vector3Stamped.h>
#include <sensor_msgs/CameraInfo.h>

#include <Eigen/Geometry>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "node_under_test.h"
#include "scbt/depth/curve_centroid.h"
#include "scbt/depth/pinhole_camera.h"
#include "scbt_ros/conversions.h"

namespace scbt::ros_test {
namespace {

using std::chrono::milliseconds;
constexpr milliseconds kReplyTimeout(10000);

// The plate's plane n . X = d (n unit, towards the camera) and the wall behind it at z = 1.6 m.
struct Plate {
  Eigen::Vector3d normal = Eigen::Vector3d(0.0, 0.25, -1.0).normalized();
  double offset = -1.0;
  double wall_z = 1.6;
};

Eigen::Vector3d on_plate(const Plate& plate, const PinholeIntrinsics& camera, const Point& pixel) {
  const Eigen::Vector3d ray = pixel_ray(camera, pixel);
  return ray * (plate.offset / plate.normal.dot(ray));
}

// Depth in millimetres (16UC1): the plate inside the true outline, the wall elsewhere.
cv::Mat render_depth(const Plate& plate, const PinholeIntrinsics& camera, const Polygon& truth,
                     cv::Size size) {
  cv::Mat mask = cv::Mat::zeros(size, CV_8UC1);
  std::vector<cv::Point> outline;
  for (const Point& p : truth) outline.emplace_back(cvRound(p.x), cvRound(p.y));
  cv::fillPoly(mask, std::vector<std::vector<cv::Point>>{outline}, cv::Scalar(255), cv::LINE_8);
  cv::Mat depth(size, CV_16UC1);
  for (int y = 0; y < size.height; ++y) {
    for (int x = 0; x < size.width; ++x) {
      const double z =
          mask.at<std::uint8_t>(y, x) ? on_plate(plate, camera, Point(x, y)).z() : plate.wall_z;
      depth.at<std::uint16_t>(y, x) = static_cast<std::uint16_t>(std::lround(z * 1000.0));
    }
  }
  return depth;
}

// The arc-length centroid of the true outline lifted onto the plate.
Eigen::Vector3d true_centroid(const Plate& plate, const PinholeIntrinsics& camera,
                              const Polygon& truth) {
  std::vector<Eigen::Vector3d> rim;
  for (const Point& p : sample_boundary(truth, 0.5)) rim.push_back(on_plate(plate, camera, p));
  return closed_curve_centroid(rim);
}

TEST(RosNode, PublishesTheRimsCentroidAndNormalWithDepth) {
  const std::string name = "scbt_depth";
  const std::vector<SceneFrame> clip = render_test_clip(SceneShape::kRim, 17, 25);
  const Plate plate;
  PinholeIntrinsics camera;  // 525 px focal length, centred
  sensor_msgs::CameraInfo info;
  info.width = 640;
  info.height = 480;
  info.distortion_model = "plumb_bob";
  info.D.assign(5, 0.0);
  info.K = {camera.fx, 0, camera.cx, 0, camera.fy, camera.cy, 0, 0, 1};

  ros::NodeHandle nh;
  ros::Publisher depth_pub = nh.advertise<sensor_msgs::Image>("/" + name + "/depth", 10);
  ros::Publisher info_pub = nh.advertise<sensor_msgs::CameraInfo>("/" + name + "/camera_info", 10);
  Inbox<geometry_msgs::PointStamped> centroids;
  Inbox<geometry_msgs::Vector3Stamped> normals;
  ros::Subscriber centroid_sub = nh.subscribe<geometry_msgs::PointStamped>(
      "/" + name + "/centroid", 100,
      [&](const geometry_msgs::PointStampedConstPtr& m) { centroids.push(*m); });
  ros::Subscriber normal_sub = nh.subscribe<geometry_msgs::Vector3Stamped>(
      "/" + name + "/normal", 100,
      [&](const geometry_msgs::Vector3StampedConstPtr& m) { normals.push(*m); });
  ros::param::set("/" + name + "/init_polygon", flatten(clip[0].truth));
  NodeUnderTest node(name, {"_use_depth:=true", "depth:=/" + name + "/depth",
                            "camera_info:=/" + name + "/camera_info"});
  ASSERT_TRUE(node.connected());
  ASSERT_TRUE(wait_until(
      [&] {
        return depth_pub.getNumSubscribers() > 0 && info_pub.getNumSubscribers() > 0 &&
               centroid_sub.getNumPublishers() > 0 && normal_sub.getNumPublishers() > 0;
      },
      milliseconds(20000)))
      << node.process.log();

  double worst_centroid = 0.0;
  double worst_angle = 0.0;
  for (size_t k = 0; k < clip.size(); ++k) {
    SCOPED_TRACE("frame " + std::to_string(k));
    const ros::Time stamp = stamp_of(static_cast<int>(k));
    const cv::Mat depth = render_depth(plate, camera, clip[k].truth, clip[k].image.size());
    info.header.stamp = stamp;
    info.header.frame_id = "scbt_test_camera";
    info_pub.publish(info);
    depth_pub.publish(to_image_msg(depth, sensor_msgs::image_encodings::TYPE_16UC1, stamp, k));
    node.publish(clip[k].image, stamp);
    const auto state = node.states.pop(kReplyTimeout);
    ASSERT_TRUE(state && node.boundaries.pop(kReplyTimeout)) << node.process.log();
    if (k == 0) {
      EXPECT_EQ((*state)["event"], "initialised");
      continue;  // the initialising frame is published back, not lifted
    }
    ASSERT_TRUE(state->contains("depth")) << state->dump();
    EXPECT_EQ((*state)["depth"]["valid"], true) << state->dump();
    const auto centroid = centroids.pop(kReplyTimeout);
    const auto normal = normals.pop(kReplyTimeout);
    ASSERT_TRUE(centroid && normal) << node.process.log();
    EXPECT_EQ(centroid->header.stamp, stamp);
    EXPECT_EQ(normal->header.stamp, stamp);
    EXPECT_EQ(centroid->header.frame_id, "scbt_test_camera");
    const Eigen::Vector3d c(centroid->point.x, centroid->point.y, centroid->point.z);
    const Eigen::Vector3d n(normal->vector.x, normal->vector.y, normal->vector.z);
    const double centroid_error = (c - true_centroid(plate, camera, clip[k].truth)).norm();
    const double angle = std::acos(std::clamp(n.dot(plate.normal), -1.0, 1.0)) * 180.0 / M_PI;
    EXPECT_LT(centroid_error, 0.005);  // metres
    EXPECT_LT(angle, 1.0);             // degrees
    worst_centroid = std::max(worst_centroid, centroid_error);
    worst_angle = std::max(worst_angle, angle);
  }
  std::cout << "[ depth    ] worst centroid error " << worst_centroid * 1000.0
            << " mm, worst normal error " << worst_angle << " deg\n";

  // A depth image of the wrong encoding: an error in the log, no crash, nothing lifted.
  const ros::Time stamp = stamp_of(100);
  info.header.stamp = stamp;
  info_pub.publish(info);
  depth_pub.publish(to_image_msg(clip[0].image, sensor_msgs::image_encodings::BGR8, stamp, 100));
  node.publish(clip.back().image, stamp);
  EXPECT_FALSE(node.states.pop(milliseconds(500)));
  EXPECT_TRUE(wait_until([&] { return node.process.log().find("depth on") != std::string::npos; },
                         milliseconds(5000)))
      << node.process.log();
  EXPECT_NE(node.process.log().find("encoding 'bgr8'"), std::string::npos) << node.process.log();
  EXPECT_TRUE(node.process.running());
  EXPECT_EQ(node.process.stop(), 0) << node.process.log();
}

}  // namespace
}  // namespace scbt::ros_test
