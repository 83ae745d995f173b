#include "scbt_ros/tracker_node.h"

#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/Vector3Stamped.h>
#include <std_msgs/Float32.h>
#include <std_msgs/String.h>

#include <exception>
#include <utility>

#include "scbt_ros/conversions.h"

namespace scbt::ros_node {

TrackerNode::TrackerNode(const ros::NodeHandle& node, const ros::NodeHandle& private_node,
                         const NodeOptions& options)
    : options_(options),
      node_(node),
      private_node_(private_node),
      transport_(node),
      tracker_(options.tracker) {
  boundary_publisher_ = private_node_.advertise<geometry_msgs::PolygonStamped>("boundary", 10);
  state_publisher_ = private_node_.advertise<std_msgs::String>("state", 10);
  confidence_publisher_ = private_node_.advertise<std_msgs::Float32>("confidence", 10);
  diagnostics_publisher_ = node_.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 10);
  // The callback only checks and hands over, so a short queue loses nothing: frames the tracker
  // cannot keep up with are dropped (and counted) in `frames_`, not here.
  constexpr uint32_t kQueue = 10;
  if (options_.use_depth) {
    centroid_publisher_ = private_node_.advertise<geometry_msgs::PointStamped>("centroid", 10);
    normal_publisher_ = private_node_.advertise<geometry_msgs::Vector3Stamped>("normal", 10);
    image_filter_.subscribe(transport_, "image", kQueue);
    depth_filter_.subscribe(transport_, "depth", kQueue);
    camera_info_filter_.subscribe(node_, "camera_info", kQueue);
    synchronizer_ = std::make_unique<message_filters::Synchronizer<SyncPolicy>>(
        SyncPolicy(options_.sync_queue_size), image_filter_, depth_filter_, camera_info_filter_);
    synchronizer_->registerCallback(&TrackerNode::on_image_and_depth, this);
  } else {
    image_subscriber_ = transport_.subscribe("image", kQueue, &TrackerNode::on_image, this);
  }
  init_subscriber_ = private_node_.subscribe("init", 1, &TrackerNode::on_init, this);
  init_box_subscriber_ = private_node_.subscribe("init_box", 1, &TrackerNode::on_init_box, this);
  if (options_.init_polygon) request_init({options_.init_polygon, std::nullopt, "~init_polygon"});
  if (options_.init_box) request_init({std::nullopt, options_.init_box, "~init_box"});
  worker_ = std::thread([this] { run_worker(); });
}

TrackerNode::~TrackerNode() {
  frames_.close();
  if (worker_.joinable()) worker_.join();
}

void TrackerNode::note_sequence(std::uint32_t seq) {
  // A smaller number is a restarted or second publisher, not a loss.
  if (last_seq_ && std::uint64_t{seq} > std::uint64_t{*last_seq_} + 1) {
    missed_ += seq - *last_seq_ - 1;
  }
  last_seq_ = seq;
}

bool TrackerNode::log_allowed(const std::string& reason) {
  return log_throttle_.allow(reason, ros::WallTime::now().toSec());
}

std::string TrackerNode::image_encoding_error(const sensor_msgs::Image& image,
                                              const std::string& topic) const {
  return "image on " + topic + " has encoding '" + image.encoding +
         "'; expected mono8, bgr8, rgb8, bgra8 or rgba8 (frame skipped)";
}

void TrackerNode::on_image(const sensor_msgs::ImageConstPtr& image) {
  note_sequence(image->header.seq);
  if (!is_tracker_encoding(image->encoding)) {
    const std::string error = image_encoding_error(*image, image_subscriber_.getTopic());
    if (log_allowed(error)) ROS_ERROR_STREAM("scbt: " << error);
    return;
  }
  frames_.put(Frame{image, nullptr, nullptr, ros::WallTime::now()});
}

void TrackerNode::on_image_and_depth(const sensor_msgs::ImageConstPtr& image,
                                     const sensor_msgs::ImageConstPtr& depth,
                                     const sensor_msgs::CameraInfoConstPtr& camera_info) {
  note_sequence(image->header.seq);
  std::string error;
  if (!is_tracker_encoding(image->encoding)) {
    error = image_encoding_error(*image, image_filter_.getTopic());
  } else if (!is_depth_encoding(depth->encoding)) {
    error = "depth on " + depth_filter_.getTopic() + " has encoding '" + depth->encoding +
            "'; expected 16UC1 (mm) or 32FC1 (m) (frame skipped)";
  } else if (depth->width != image->width || depth->height != image->height) {
    error = "depth is " + std::to_string(depth->width) + "x" + std::to_string(depth->height) +
            " but the image is " + std::to_string(image->width) + "x" +
            std::to_string(image->height) + "; register depth to the colour camera (frame skipped)";
  }
  if (!error.empty()) {
    if (log_allowed(error)) ROS_ERROR_STREAM("scbt: " << error);
    return;
  }
  frames_.put(Frame{image, depth, camera_info, ros::WallTime::now()});
}

void TrackerNode::on_init(const geometry_msgs::PolygonStampedConstPtr& polygon) {
  request_init({from_polygon_msg(polygon->polygon), std::nullopt, init_subscriber_.getTopic()});
}

void TrackerNode::on_init_box(const sensor_msgs::RegionOfInterestConstPtr& box) {
  try {
    request_init({std::nullopt, from_roi_msg(*box), init_box_subscriber_.getTopic()});
  } catch (const std::exception& e) {
    ROS_ERROR_STREAM("scbt: box on " << init_box_subscriber_.getTopic()
                                     << " ignored: " << e.what());
  }
}

void TrackerNode::request_init(PendingInit init) {
  std::lock_guard<std::mutex> lock(init_mutex_);
  pending_init_ = std::move(init);
}

bool TrackerNode::apply_init(const PendingInit& init, const cv::Mat& image) {
  try {
    if (init.box) {
      const Polygon found = tracker_.init_from_box(image, *init.box);
      ROS_INFO_STREAM("scbt: initialised from the box on "
                      << init.source << " (" << init.box->width << "x" << init.box->height << " at "
                      << init.box->x << "," << init.box->y << "): a boundary of " << found.size()
                      << " vertices");
    } else {
      tracker_.init(image, *init.polygon);
      ROS_INFO_STREAM("scbt: initialised from " << init.source << " with " << init.polygon->size()
                                                << " vertices");
    }
    return true;
  } catch (const std::exception& e) {
    // The tracker keeps the boundary it had, if any.
    ROS_ERROR_STREAM("scbt: initial " << (init.box ? "box" : "boundary") << " from " << init.source
                                      << " rejected: " << e.what());
    return false;
  }
}

void TrackerNode::run_worker() {
  while (std::optional<Frame> frame = frames_.take()) {
    try {
      process(*frame);
    } catch (const std::exception& e) {
      // A frame the tracker cannot take (e.g. another size than the one it was initialised on).
      if (log_allowed(e.what())) {
        ROS_ERROR_STREAM("scbt: frame " << frame->image->header.seq
                                        << " not tracked: " << e.what());
      }
      FrameReport report{FrameEvent::kFailed};
      report.reason = e.what();
      publish_state(*frame, report);
    }
  }
}

void TrackerNode::process(const Frame& frame) {
  ++frames_taken_;
  const cv::Mat image = to_tracker_image(frame.image);
  std::optional<PendingInit> init;
  {
    std::lock_guard<std::mutex> lock(init_mutex_);
    std::swap(init, pending_init_);
  }
  if (init && apply_init(*init, image)) {
    boundary_publisher_.publish(to_polygon_msg(tracker_.boundary(), frame.image->header));
    publish_state(frame, FrameReport{FrameEvent::kInitialised});
    return;
  }
  if (!tracker_.initialized()) {
    ROS_INFO_THROTTLE(10.0, "scbt: waiting for an initial boundary on ~init or ~init_box");
    publish_state(frame, FrameReport{FrameEvent::kWaiting});
    return;
  }
  const TrackResult result = tracker_.track(image);
  boundary_publisher_.publish(to_polygon_msg(result.boundary, frame.image->header));
  FrameReport report{FrameEvent::kTracked};
  report.result = &result;
  std::optional<Boundary3d> lifted;
  if (frame.depth) {
    const auto start = ros::WallTime::now();
    lifted = lift_to_3d(frame, result.boundary);
    report.depth_ms = (ros::WallTime::now() - start).toSec() * 1e3;
    report.boundary_3d = &*lifted;
  }
  publish_state(frame, report);
}

Boundary3d TrackerNode::lift_to_3d(const Frame& frame, const Polygon& boundary) {
  const Boundary3d lifted =
      lift_boundary_to_3d(boundary, to_depth_image(frame.depth),
                          from_camera_info_msg(*frame.camera_info), options_.depth);
  if (!lifted.valid) {
    if (log_allowed("too little depth along the boundary")) {
      ROS_WARN_STREAM("scbt: too little depth along the boundary ("
                      << lifted.n_valid << " of " << lifted.n_samples
                      << " samples): no centroid or normal published");
    }
    return lifted;
  }
  // Depth registered to the colour image shares its frame: the image's header stamps both.
  geometry_msgs::PointStamped centroid;
  centroid.header = frame.image->header;
  centroid.point.x = lifted.centroid.x();
  centroid.point.y = lifted.centroid.y();
  centroid.point.z = lifted.centroid.z();
  centroid_publisher_.publish(centroid);
  geometry_msgs::Vector3Stamped normal;
  normal.header = frame.image->header;
  normal.vector.x = lifted.normal.x();
  normal.vector.y = lifted.normal.y();
  normal.vector.z = lifted.normal.z();
  normal_publisher_.publish(normal);
  return lifted;
}

void TrackerNode::publish_state(const Frame& frame, const FrameReport& partial) {
  FrameReport report = partial;
  report.frame = frames_taken_;
  report.dropped_total = frames_.dropped();
  report.dropped_since_last = report.dropped_total - dropped_reported_;
  dropped_reported_ = report.dropped_total;
  report.missed_total = missed_;
  report.latency_ms = (ros::WallTime::now() - frame.received).toSec() * 1e3;
  std_msgs::String msg;
  msg.data = state_json(report);
  state_publisher_.publish(msg);
  if (report.result) {
    std_msgs::Float32 confidence;
    confidence.data = static_cast<float>(report.result->confidence);
    confidence_publisher_.publish(confidence);
  }
  diagnostic_msgs::DiagnosticArray diagnostics;
  diagnostics.header.stamp = frame.image->header.stamp;
  diagnostics.status.push_back(
      diagnostic_status(report, ros::this_node::getName() + ": boundary tracking"));
  const int level = diagnostics.status.back().level;
  const ros::WallTime now = ros::WallTime::now();
  if (level != last_diagnostic_level_ || (now - last_diagnostic_).toSec() >= 1.0) {
    diagnostics_publisher_.publish(diagnostics);
    last_diagnostic_ = now;
    last_diagnostic_level_ = level;
  }
}

}  // namespace scbt::ros_node
