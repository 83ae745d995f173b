#include "scbt/depth/boundary_3d_io.h"

#include <cmath>
#include <cstdio>

namespace scbt {
namespace {

std::string number(double value) {
  if (!std::isfinite(value)) return "nan";
  char text[32];
  std::snprintf(text, sizeof text, "%.6f", value);
  return text;
}

}  // namespace

void write_points3d_header(std::ostream& csv) {
  csv << "frame,valid,x,y,z,nx,ny,nz,radius,rms,n_valid,n_samples\n";
}

void write_points3d_row(std::ostream& csv, int frame, const Boundary3d& rim) {
  const bool valid = rim.valid;
  auto field = [valid](double value) { return valid ? number(value) : std::string("nan"); };
  csv << frame << ',' << (valid ? 1 : 0);
  for (int k = 0; k < 3; ++k) csv << ',' << field(rim.centroid[k]);
  for (int k = 0; k < 3; ++k) csv << ',' << field(rim.normal[k]);
  csv << ',' << (rim.circle.found ? field(rim.circle.radius) : std::string("nan")) << ','
      << field(rim.rms) << ',' << rim.n_valid << ',' << rim.n_samples << '\n';
}

std::string format_boundary3d_line(const Boundary3d& rim) {
  std::string line;
  int count = 0;
  for (const Eigen::Vector3d& p : rim.points) {
    if (!p.allFinite()) continue;
    ++count;
    for (int k = 0; k < 3; ++k) line += ' ' + number(p[k]);
  }
  return std::to_string(count) + line;
}

}  // namespace scbt
