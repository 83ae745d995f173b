// The node's settings, read from its private ROS parameters (`~filter_distance`, ...): every option
// of the tracker's option table (scbt/tracker/option_table.h) under its name (the CLI's with
// underscores) and default, plus how the node is wired and initialised.
#pragma once

#include <xmlrpcpp/XmlRpcValue.h>

#include <functional>
#include <opencv2/core/types.hpp>
#include <optional>
#include <string>
#include <vector>

#include "scbt/depth/depth_options.h"
#include "scbt/geometry/polygon.h"
#include "scbt/tracker/tracker_options.h"

namespace ros {
class NodeHandle;
}

namespace scbt::ros_node {

struct NodeOptions {
  TrackerOptions tracker;
  // Subscribe to `depth` and `camera_info` too, synchronised with `image`, and publish the
  // boundary's 3-D centroid and normal.
  bool use_depth = false;
  // How the boundary is lifted to 3-D with depth (~min_depth, ~max_depth in metres).
  DepthOptions depth;
  // Messages the synchroniser keeps per topic while matching stamps (ApproximateTime).
  int sync_queue_size = 10;
  // The initial boundary from `~init_polygon` [x1, y1, x2, y2, ...] (pixels), or the most
  // salient closed boundary inside `~init_box` [x, y, w, h] (Tracker::init_from_box); applied to
  // the first frame that arrives. At most one of them is set.
  std::optional<Polygon> init_polygon;
  std::optional<cv::Rect> init_box;

  // Throws std::invalid_argument naming the first bad value.
  void check() const;
};

// Reads the private parameters of `private_node`. Throws std::invalid_argument naming the
// parameter for a wrong type (a string where a number belongs, ...), an unknown detector name,
// a malformed polygon or box, or an option out of range.
NodeOptions read_node_options(const ros::NodeHandle& private_node);

// The tracker options from parameters named as the option table's options: `lookup(name, &value)`
// fetches one (false when it is not set), `resolve(name)` gives its full name for messages. Throws
// std::invalid_argument "parameter FULL_NAME: MESSAGE", MESSAGE the table's, for a bad value.
using ParameterLookup = std::function<bool(const std::string& name, XmlRpc::XmlRpcValue* value)>;
TrackerOptions tracker_options_from_parameters(
    const ParameterLookup& lookup, const std::function<std::string(const std::string&)>& resolve);

// The private parameters the node reads, without the leading '~'.
std::vector<std::string> node_parameter_names();

// Private parameters that are set but that the node does not know (likely typos).
std::vector<std::string> unknown_parameters(const ros::NodeHandle& private_node);

// The box (x, y, width, height) in whole pixels (rounded). Throws std::invalid_argument for a
// value beyond an int (naming it), a negative corner or a non-positive width or height.
cv::Rect pixel_box(double x, double y, double width, double height);

}  // namespace scbt::ros_node
