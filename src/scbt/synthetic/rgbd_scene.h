// RGB-D scenes rendered in code with exact ground truth (issue 20): a bowl with a circular rim or
// a closed rectangular box standing on a textured table, seen by a pinhole camera (optionally
// with lens distortion) as a colour image and an aligned 16-bit depth image carrying the
// artefacts of a real sensor (rgbd_sensor.h). The truth of every frame is the rim in 3-D (the
// bowl's lip edge, the box's top face), its centre, normal and radius, and its projection.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

#include "scbt/depth/pinhole_camera.h"
#include "scbt/geometry/polygon.h"

namespace scbt {

enum class RimShape {
  kBowl,  // a spherical bowl with a flat lip; its inside is lower than its rim
  kBox,   // a closed box; the rim is its top face's outline
};

// Parses "bowl" or "box"; throws std::invalid_argument otherwise.
RimShape parse_rim_shape(const std::string& name);

// Where the object is: the rim's centre (camera frame, metres), the rim plane's normal (out of
// the bowl's opening / the box's top, towards the camera) and a turn about that normal.
struct RimPose {
  Eigen::Vector3d centre{0.0, 0.0, 0.6};
  Eigen::Vector3d normal = Eigen::Vector3d(0.0, -0.7071067811865476, -0.7071067811865476);
  double spin = 0.0;  // radians about the normal
};

struct RgbdSceneOptions {
  cv::Size size{640, 480};
  PinholeIntrinsics camera;  // Kinect-like defaults (fx = fy = 525, centre 319.5, 239.5)
  RimShape shape = RimShape::kBowl;
  std::uint32_t seed = 1;  // noise, holes and the table's texture derive from it

  double rim_radius = 0.10;  // bowl: radius of the lip's outer edge (m)
  double lip_width = 0.006;  // bowl: width of the flat lip (m)
  double bowl_depth = 0.06;  // bowl: from the rim down to its bottom (m)
  double box_length = 0.24;  // box: top face along its first axis (m)
  double box_width = 0.16;   // box: top face along its second axis (m)
  double box_height = 0.10;  // box: from the top face down to the table (m)
  int rim_vertices = 90;     // vertices of the bowl's true outline; box edges are split in
  int box_edge_pieces = 1;   // this many pieces (more for a distorted camera's curved edges)

  double image_noise_sigma = 2.0;  // colour noise (grey levels)

  // Throws std::invalid_argument naming the first bad value (the camera's included).
  void check() const;
};

struct RgbdFrame {
  cv::Mat colour;       // CV_8UC3
  cv::Mat depth;        // CV_16UC1 (millimetres unless the sensor's scale says otherwise), 0 = none
  cv::Mat clean_depth;  // CV_32FC1 metres, exact, before the sensor's artefacts
  Polygon truth;        // the rim's projection (the boundary a tracker should report)
  std::vector<Eigen::Vector3d> truth_rim;  // the same points in 3-D
  Eigen::Vector3d centre;                  // the rim's centre (metres, camera frame)
  Eigen::Vector3d normal;                  // unit, towards the camera
  double radius = 0.0;                     // bowl: the rim's radius; box: 0
};

// The exact scene at `pose`: colour (2x2 supersampled, then noise seeded by (seed, frame_index)),
// exact depth (pixel centres), and the truth. The sensor's artefacts are added by
// apply_depth_sensor (rgbd_sensor.h); `depth` here is clean_depth in millimetres.
RgbdFrame render_rgbd_frame(const RgbdSceneOptions& options, const RimPose& pose,
                            int frame_index = 0);

// A known 3-D path: the rim's centre moves from `start` to `end` with a sideways and vertical
// sway of `sway` metres, its tilt (angle between the normal and the direction to the camera)
// swings between tilt_min and tilt_max radians, and the object turns about its normal by up to
// `spin` radians. Frame 0 is at `start`.
struct RimPathOptions {
  Eigen::Vector3d start{0.0, 0.0, 0.6};
  Eigen::Vector3d end{0.02, 0.01, 0.62};
  double sway = 0.01;
  double tilt_min = 0.6;
  double tilt_max = 0.85;
  double spin = 0.2;

  void check() const;
};

std::vector<RimPose> rim_path(const RimPathOptions& options, int frames);

}  // namespace scbt
