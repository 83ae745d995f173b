// scbt_node: the salient closed boundary tracker as a ROS 1 node (see docs/ros.md).
#include <ros/ros.h>

#include <exception>

#include "scbt_ros/node_options.h"
#include "scbt_ros/tracker_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "scbt");
  ros::NodeHandle node;
  ros::NodeHandle private_node("~");
  scbt::ros_node::NodeOptions options;
  try {
    options = scbt::ros_node::read_node_options(private_node);
  } catch (const std::exception& e) {
    ROS_FATAL_STREAM("scbt: " << e.what());
    return 2;
  }
  for (const std::string& name : scbt::ros_node::unknown_parameters(private_node)) {
    ROS_WARN_STREAM("scbt: unknown parameter " << name << " ignored");
  }
  scbt::ros_node::TrackerNode tracker_node(node, private_node, options);
  ros::spin();
  return 0;
}
