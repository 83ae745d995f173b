// The rim in 3-D drawn over the frame (scbt track --depth --video): the projected centroid, the
// plane's normal as an arrow, and the distance.
#pragma once

#include <opencv2/core/mat.hpp>

#include "scbt/depth/boundary_3d.h"
#include "scbt/depth/pinhole_camera.h"

namespace scbt {

// Draws onto a BGR image: a cross at the projected centroid, an arrow from it along the normal
// (normal_length metres), the circle's projection when one was found, and "z 0.612 m"; for an
// invalid result only "no 3-D (n_valid/n_samples)". Points behind the camera are not drawn.
void draw_rim_3d(cv::Mat* image, const Boundary3d& rim, const PinholeIntrinsics& camera,
                 double normal_length = 0.05);

}  // namespace scbt
