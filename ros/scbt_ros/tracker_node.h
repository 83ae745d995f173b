// The scbt ROS node: images in (optionally with synchronised depth and camera info), the tracked
// boundary, its state and (with depth) its 3-D centroid and normal out, stamped with the image's
// header. ROS callbacks only hand frames over; a worker thread tracks the newest one.
#pragma once

#include <geometry_msgs/PolygonStamped.h>
#include <image_transport/image_transport.h>
#include <image_transport/subscriber_filter.h>
#include <message_filters/subscriber.h>
#include <message_filters/sync_policies/approximate_time.h>
#include <message_filters/synchronizer.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/RegionOfInterest.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "scbt/depth/boundary_3d.h"
#include "scbt/tracker/tracker.h"
#include "scbt_ros/latest_slot.h"
#include "scbt_ros/node_options.h"
#include "scbt_ros/reason_throttle.h"
#include "scbt_ros/state_report.h"

namespace scbt::ros_node {

class TrackerNode {
 public:
  // Subscribes and advertises on `node` (topics image, depth, camera_info) and `private_node`
  // (~init, ~init_box in; ~boundary, ~state, ~confidence, ~centroid, ~normal out), publishes
  // /diagnostics, and starts the worker.
  TrackerNode(const ros::NodeHandle& node, const ros::NodeHandle& private_node,
              const NodeOptions& options);
  ~TrackerNode();  // stops and joins the worker
  TrackerNode(const TrackerNode&) = delete;
  TrackerNode& operator=(const TrackerNode&) = delete;

 private:
  struct Frame {
    sensor_msgs::ImageConstPtr image;
    sensor_msgs::ImageConstPtr depth;  // null without depth
    sensor_msgs::CameraInfoConstPtr camera_info;
    ros::WallTime received;
  };
  // A polygon to start from, or a box to find the boundary in (Tracker::init_from_box).
  struct PendingInit {
    std::optional<Polygon> polygon;
    std::optional<cv::Rect> box;
    std::string source;  // for the log: "~init", "~init_box" or a parameter
  };

  void on_image(const sensor_msgs::ImageConstPtr& image);
  void on_image_and_depth(const sensor_msgs::ImageConstPtr& image,
                          const sensor_msgs::ImageConstPtr& depth,
                          const sensor_msgs::CameraInfoConstPtr& camera_info);
  void on_init(const geometry_msgs::PolygonStampedConstPtr& polygon);
  void on_init_box(const sensor_msgs::RegionOfInterestConstPtr& box);
  void request_init(PendingInit init);
  // Applies `init` to `image`; false (and an error in the log) when the tracker rejects it.
  bool apply_init(const PendingInit& init, const cv::Mat& image);
  // Counts the images missing between this one's header.seq and the previous one's.
  void note_sequence(std::uint32_t seq);
  // Whether an error or warning for `reason` is logged now: each reason at most once per 5 s
  // (log_throttle_), a different one at once.
  bool log_allowed(const std::string& reason);
  std::string image_encoding_error(const sensor_msgs::Image& image, const std::string& topic) const;

  void run_worker();
  void process(const Frame& frame);
  void publish_state(const Frame& frame, const FrameReport& report);
  // The boundary on the frame's depth: publishes ~centroid and ~normal when it is valid.
  Boundary3d lift_to_3d(const Frame& frame, const Polygon& boundary);

  NodeOptions options_;
  ros::NodeHandle node_;
  ros::NodeHandle private_node_;
  image_transport::ImageTransport transport_;
  image_transport::Subscriber image_subscriber_;
  // With depth: image, depth and camera info matched by stamp.
  using SyncPolicy =
      message_filters::sync_policies::ApproximateTime<sensor_msgs::Image, sensor_msgs::Image,
                                                      sensor_msgs::CameraInfo>;
  image_transport::SubscriberFilter image_filter_;
  image_transport::SubscriberFilter depth_filter_;
  message_filters::Subscriber<sensor_msgs::CameraInfo> camera_info_filter_;
  std::unique_ptr<message_filters::Synchronizer<SyncPolicy>> synchronizer_;
  ros::Subscriber init_subscriber_;
  ros::Subscriber init_box_subscriber_;
  ros::Publisher boundary_publisher_;
  ros::Publisher state_publisher_;
  ros::Publisher confidence_publisher_;
  ros::Publisher diagnostics_publisher_;
  ros::Publisher centroid_publisher_;
  ros::Publisher normal_publisher_;

  LatestSlot<Frame> frames_;
  // Images that never reached the callback (ROS's subscriber queue overflowed, or upstream), seen
  // as gaps in header.seq. The callbacks' own (one spinner thread); the worker reads the count.
  std::optional<std::uint32_t> last_seq_;
  std::atomic<std::uint64_t> missed_{0};
  std::mutex init_mutex_;
  std::optional<PendingInit> pending_init_;
  ReasonThrottle log_throttle_{5.0};  // the callbacks' and the worker's

  // The worker's own.
  Tracker tracker_;
  std::uint64_t frames_taken_ = 0;
  std::uint64_t dropped_reported_ = 0;
  // /diagnostics is published when the level changes and at most once a second otherwise.
  ros::WallTime last_diagnostic_;
  int last_diagnostic_level_ = -1;
  std::thread worker_;
};

}  // namespace scbt::ros_node
