#include "scbt/depth/pinhole_camera.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "scbt/depth/lens_distortion.h"

namespace scbt {

void PinholeIntrinsics::check() const {
  auto fail = [](const std::string& what) {
    throw std::invalid_argument("camera intrinsics: " + what);
  };
  if (!(std::isfinite(fx) && fx > 0.0)) fail("fx must be a positive number");
  if (!(std::isfinite(fy) && fy > 0.0)) fail("fy must be a positive number");
  if (!std::isfinite(cx)) fail("cx must be finite");
  if (!std::isfinite(cy)) fail("cy must be finite");
  const std::size_t n = distortion.size();
  if (n != 0 && n != 4 && n != 5 && n != 8)
    fail("distortion needs 0, 4, 5 or 8 coefficients (k1 k2 p1 p2 [k3 [k4 k5 k6]]), got " +
         std::to_string(n));
  for (double k : distortion)
    if (!std::isfinite(k)) fail("distortion coefficients must be finite");
}

bool PinholeIntrinsics::has_distortion() const {
  for (double k : distortion)
    if (k != 0.0) return true;
  return false;
}

PinholeIntrinsics parse_intrinsics(const std::string& text) {
  std::vector<double> values;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    std::size_t used = 0;
    double value = 0.0;
    try {
      value = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || item.find_first_not_of(" \t", used) != std::string::npos)
      throw std::invalid_argument("intrinsics '" + text + "': '" + item + "' is not a number");
    values.push_back(value);
  }
  if (values.size() != 4)
    throw std::invalid_argument("intrinsics '" + text +
                                "': expected fx,fy,cx,cy (4 numbers), got " +
                                std::to_string(values.size()));
  PinholeIntrinsics camera;
  camera.fx = values[0];
  camera.fy = values[1];
  camera.cx = values[2];
  camera.cy = values[3];
  camera.check();
  return camera;
}

Eigen::Vector2d undistorted_normalised(const PinholeIntrinsics& camera, const Point& pixel) {
  const Eigen::Vector2d distorted((pixel.x - camera.cx) / camera.fx,
                                  (pixel.y - camera.cy) / camera.fy);
  return undistort_normalised(camera.distortion, distorted);
}

Eigen::Vector3d pixel_ray(const PinholeIntrinsics& camera, const Point& pixel) {
  const Eigen::Vector2d xy = undistorted_normalised(camera, pixel);
  return {xy.x(), xy.y(), 1.0};
}

Point project_point(const PinholeIntrinsics& camera, const Eigen::Vector3d& point) {
  const Eigen::Vector2d ideal(point.x() / point.z(), point.y() / point.z());
  const Eigen::Vector2d xy =
      camera.distortion.empty() ? ideal : distort_normalised(camera.distortion, ideal);
  return {camera.fx * xy.x() + camera.cx, camera.fy * xy.y() + camera.cy};
}

Polygon undistort_polygon(const PinholeIntrinsics& camera, const Polygon& polygon) {
  if (!camera.has_distortion()) return polygon;
  Polygon ideal;
  ideal.reserve(polygon.size());
  for (const Point& p : polygon) {
    const Eigen::Vector2d xy = undistorted_normalised(camera, p);
    ideal.emplace_back(camera.fx * xy.x() + camera.cx, camera.fy * xy.y() + camera.cy);
  }
  return ideal;
}

}  // namespace scbt
