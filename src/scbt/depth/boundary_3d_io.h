// Text outputs of the lift to 3-D: the per-frame CSV of `scbt track --points3d` and the
// per-frame 3-D point lines of `--boundary3d`.
#pragma once

#include <ostream>
#include <string>

#include "scbt/depth/boundary_3d.h"

namespace scbt {

// "frame,valid,x,y,z,nx,ny,nz,radius,rms,n_valid,n_samples".
void write_points3d_header(std::ostream& csv);

// One row: metres in the camera frame (x right, y down, z forward), the centroid and the
// plane's normal; radius is the circle's when the rim is near-circular, else nan; an invalid
// result (valid 0) has nan for every number but the counts.
void write_points3d_row(std::ostream& csv, int frame, const Boundary3d& rim);

// "n x1 y1 z1 ... xn yn zn": the valid measured points in boundary order (metres, 6 decimals);
// "0" when there are none.
std::string format_boundary3d_line(const Boundary3d& rim);

}  // namespace scbt
