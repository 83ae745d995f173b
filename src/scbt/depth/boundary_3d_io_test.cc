#include "scbt/depth/boundary_3d_io.h"

#include <gtest/gtest.h>

#include <limits>
#include <sstream>

namespace scbt {
namespace {

TEST(Boundary3dIo, RowsAndLines) {
  Boundary3d rim;
  rim.valid = true;
  rim.n_valid = 2;
  rim.n_samples = 3;
  rim.centroid = {0.1, -0.2, 0.75};
  rim.normal = {0.0, -0.6, -0.8};
  rim.rms = 0.0012;
  rim.circle.found = true;
  rim.circle.radius = 0.1;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  rim.points = {{0.1, 0.2, 0.7}, {nan, nan, nan}, {0.3, 0.4, 0.8}};
  std::ostringstream csv;
  write_points3d_header(csv);
  write_points3d_row(csv, 7, rim);
  rim.valid = false;
  rim.circle.found = false;
  write_points3d_row(csv, 8, rim);
  EXPECT_EQ(csv.str(),
            "frame,valid,x,y,z,nx,ny,nz,radius,rms,n_valid,n_samples\n"
            "7,1,0.100000,-0.200000,0.750000,0.000000,-0.600000,-0.800000,0.100000,0.001200,2,3\n"
            "8,0,nan,nan,nan,nan,nan,nan,nan,nan,2,3\n");
  EXPECT_EQ(format_boundary3d_line(rim), "2 0.100000 0.200000 0.700000 0.300000 0.400000 0.800000");
  EXPECT_EQ(format_boundary3d_line(Boundary3d{}), "0");
}

}  // namespace
}  // namespace scbt
