// Python bindings of the lift to 3-D (src/scbt/depth): a tracked boundary and an aligned depth
// image (numpy uint16 in depth_scale units, or float32 metres) to the rim's 3-D points,
// centroid, plane and circle.
#include "depth_bindings.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <opencv2/core/mat.hpp>
#include <set>
#include <string>

#include "scbt/depth/boundary_3d.h"
#include "scbt/depth/camera_info.h"

namespace py = pybind11;

namespace scbt {
namespace {

std::string shape_of(const py::array& a) {
  std::string text = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) text += (i ? ", " : "") + std::to_string(a.shape(i));
  return text + (a.ndim() == 1 ? ",)" : ")");
}

Polygon to_polygon(const py::object& object) {
  const auto array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(object);
  if (!array) {
    PyErr_Clear();
    throw py::type_error("boundary must be an (N, 2) array of x, y pixel coordinates");
  }
  if (array.ndim() != 2 || array.shape(1) != 2)
    throw py::value_error("boundary must have shape (N, 2), got " + shape_of(array));
  Polygon polygon(static_cast<std::size_t>(array.shape(0)));
  const auto view = array.unchecked<2>();
  for (py::ssize_t i = 0; i < array.shape(0); ++i) {
    if (!std::isfinite(view(i, 0)) || !std::isfinite(view(i, 1)))
      throw py::value_error("boundary has a non-finite coordinate at row " + std::to_string(i));
    polygon[i] = Point(view(i, 0), view(i, 1));
  }
  return polygon;
}

// The depth image as a cv::Mat header over a C-contiguous copy or view held in `keep`.
cv::Mat to_depth_mat(const py::object& object, py::array* keep) {
  if (!py::isinstance<py::array>(object))
    throw py::type_error("depth must be a numpy.ndarray of dtype uint16 or float32");
  py::array array = py::reinterpret_borrow<py::array>(object);
  const bool u16 = array.dtype().is(py::dtype::of<std::uint16_t>());
  const bool f32 = array.dtype().is(py::dtype::of<float>());
  if (!u16 && !f32)
    throw py::type_error(
        "depth must have dtype uint16 (depth_scale units) or float32 (metres), got " +
        py::str(array.dtype()).cast<std::string>());
  if (array.ndim() != 2 || array.shape(0) == 0 || array.shape(1) == 0)
    throw py::value_error("depth must have shape (H, W), got " + shape_of(array));
  array = py::array::ensure(array, py::array::c_style);
  *keep = array;
  return cv::Mat(static_cast<int>(array.shape(0)), static_cast<int>(array.shape(1)),
                 u16 ? CV_16UC1 : CV_32FC1, const_cast<void*>(array.data()));
}

PinholeIntrinsics to_camera(const py::object& intrinsics, const py::object& distortion) {
  std::vector<double> values;
  try {
    const auto array =
        py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(intrinsics);
    if (!array) throw py::error_already_set();
    const double* data = array.data();
    values.assign(data, data + array.size());
    if (array.ndim() == 2 && array.shape(0) == 3 && array.shape(1) == 3)
      values = {data[0], data[4], data[2], data[5]};  // a 3x3 camera matrix K
  } catch (const py::error_already_set&) {
    PyErr_Clear();
    throw py::type_error("intrinsics must be (fx, fy, cx, cy) or a 3x3 camera matrix");
  }
  if (values.size() != 4)
    throw py::value_error("intrinsics must be (fx, fy, cx, cy) or a 3x3 camera matrix");
  PinholeIntrinsics camera;
  camera.fx = values[0];
  camera.fy = values[1];
  camera.cx = values[2];
  camera.cy = values[3];
  if (!distortion.is_none()) camera.distortion = distortion.cast<std::vector<double>>();
  try {
    camera.check();
  } catch (const std::invalid_argument& e) {
    throw py::value_error(e.what());
  }
  return camera;
}

DepthOptions options_from_kwargs(const py::kwargs& kwargs) {
  DepthOptions o;
  std::set<std::string> used;
  auto take = [&](const char* name, auto* field) {
    if (!kwargs.contains(name)) return;
    *field = kwargs[name].cast<std::remove_pointer_t<decltype(field)>>();
    used.insert(name);
  };
  take("depth_scale", &o.depth_scale);
  take("min_depth", &o.min_depth);
  take("max_depth", &o.max_depth);
  take("sample_step", &o.sample_step);
  take("window_offset", &o.window_offset);
  take("window_length", &o.window_length);
  take("window_half_width", &o.window_half_width);
  take("noise_at_1m", &o.noise_at_1m);
  take("outlier_sigmas", &o.outlier_sigmas);
  take("tolerance_floor", &o.tolerance_floor);
  take("min_surface_pixels", &o.min_surface_pixels);
  take("neighbour_span", &o.neighbour_span);
  take("plane_iterations", &o.plane_iterations);
  take("min_valid_points", &o.min_valid_points);
  take("min_valid_fraction", &o.min_valid_fraction);
  take("circle_max_relative_rms", &o.circle_max_relative_rms);
  for (const auto& item : kwargs) {
    const std::string name = py::str(item.first);
    if (!used.count(name)) throw py::type_error("unknown depth option '" + name + "'");
  }
  try {
    o.check();
  } catch (const std::invalid_argument& e) {
    throw py::value_error(e.what());
  }
  return o;
}

py::array_t<double> vector3(const Eigen::Vector3d& v) {
  py::array_t<double> array(3);
  for (int i = 0; i < 3; ++i) array.mutable_at(i) = v[i];
  return array;
}

py::array_t<double> points_array(const std::vector<Eigen::Vector3d>& points) {
  py::array_t<double> array({static_cast<py::ssize_t>(points.size()), py::ssize_t{3}});
  auto view = array.mutable_unchecked<2>();
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < 3; ++k) view(i, k) = points[i][k];
  return array;
}

}  // namespace

void register_depth(py::module_& m) {
  py::class_<Boundary3d>(m, "Boundary3d",
                         "The rim in 3-D (metres, camera frame: x right, y down, z forward); "
                         "see lift_boundary_to_3d.")
      .def_readonly("valid", &Boundary3d::valid, "enough consistent depth and a plane was found")
      .def_readonly("n_samples", &Boundary3d::n_samples)
      .def_readonly("n_valid", &Boundary3d::n_valid, "samples whose depth passed every check")
      .def_property_readonly(
          "samples",
          [](const Boundary3d& b) {
            py::array_t<double> array({static_cast<py::ssize_t>(b.samples.size()), py::ssize_t{2}});
            auto view = array.mutable_unchecked<2>();
            for (std::size_t i = 0; i < b.samples.size(); ++i)
              view(i, 0) = b.samples[i].x, view(i, 1) = b.samples[i].y;
            return array;
          },
          "(N, 2) image points where depth was read")
      .def_property_readonly(
          "points", [](const Boundary3d& b) { return points_array(b.points); },
          "(N, 3) measured 3-D points, NaN rows where rejected")
      .def_property_readonly(
          "curve", [](const Boundary3d& b) { return points_array(b.curve); },
          "(N, 3) each sample's ray on the fitted plane")
      .def_property_readonly(
          "centroid", [](const Boundary3d& b) { return vector3(b.centroid); },
          "arc-length centroid of the rim (3,)")
      .def_property_readonly(
          "normal", [](const Boundary3d& b) { return vector3(b.normal); },
          "unit normal of the rim's plane, towards the camera (3,)")
      .def_readonly("plane_offset", &Boundary3d::plane_offset, "the plane is normal . x = offset")
      .def_readonly("rms", &Boundary3d::rms, "RMS distance of the valid points to the plane")
      .def_property_readonly("circle_found", [](const Boundary3d& b) { return b.circle.found; })
      .def_property_readonly("circle_centre",
                             [](const Boundary3d& b) { return vector3(b.circle.centre); })
      .def_property_readonly("circle_normal",
                             [](const Boundary3d& b) { return vector3(b.circle.normal); })
      .def_property_readonly("circle_radius", [](const Boundary3d& b) { return b.circle.radius; })
      .def_property_readonly("circle_rms", [](const Boundary3d& b) { return b.circle.rms; })
      .def("__repr__", [](const Boundary3d& b) {
        return "Boundary3d(valid=" + std::string(b.valid ? "True" : "False") +
               ", n_valid=" + std::to_string(b.n_valid) + "/" + std::to_string(b.n_samples) + ")";
      });

  m.def(
      "lift_boundary_to_3d",
      [](const py::object& boundary, const py::object& depth, const py::object& intrinsics,
         const py::object& distortion, const py::kwargs& kwargs) {
        const Polygon polygon = to_polygon(boundary);
        py::array keep;
        const cv::Mat depth_mat = to_depth_mat(depth, &keep);
        const PinholeIntrinsics camera = to_camera(intrinsics, distortion);
        const DepthOptions options = options_from_kwargs(kwargs);
        py::gil_scoped_release release;
        return lift_boundary_to_3d(polygon, depth_mat, camera, options);
      },
      py::arg("boundary"), py::arg("depth"), py::arg("intrinsics"),
      py::arg("distortion") = py::none(),
      "Lifts an (N, 2) boundary to 3-D with an aligned depth image: uint16 (H, W) in depth_scale\n"
      "metres per unit (default 0.001) or float32 (H, W) metres; 0 = no depth. intrinsics is\n"
      "(fx, fy, cx, cy) or a 3x3 camera matrix; distortion OpenCV's k1 k2 p1 p2 [k3 [k4 k5 k6]].\n"
      "Keyword options: depth_scale, min_depth, max_depth, sample_step, window_offset,\n"
      "window_length, window_half_width, noise_at_1m, outlier_sigmas, tolerance_floor,\n"
      "min_surface_pixels, neighbour_span, plane_iterations, min_valid_points,\n"
      "min_valid_fraction, circle_max_relative_rms. Returns a Boundary3d.");

  m.def(
      "read_camera_info",
      [](const std::string& path) {
        PinholeIntrinsics camera;
        try {
          camera = read_camera_info(path);
        } catch (const std::runtime_error& e) {
          throw py::value_error(e.what());
        }
        py::dict info;
        info["intrinsics"] = py::make_tuple(camera.fx, camera.fy, camera.cx, camera.cy);
        info["distortion"] = camera.distortion;
        return info;
      },
      py::arg("path"),
      "Intrinsics from a ROS camera_info YAML or an OpenCV calibration file: a dict with\n"
      "'intrinsics' (fx, fy, cx, cy) and 'distortion' (list). Raises ValueError naming the\n"
      "problem.");

  m.def(
      "project_points",
      [](const py::object& points, const py::object& intrinsics, const py::object& distortion) {
        const PinholeIntrinsics camera = to_camera(intrinsics, distortion);
        const auto array =
            py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(points);
        if (!array || array.ndim() != 2 || array.shape(1) != 3) {
          PyErr_Clear();
          throw py::value_error("points must be an (N, 3) array");
        }
        py::array_t<double> pixels({array.shape(0), py::ssize_t{2}});
        auto in = array.unchecked<2>();
        auto out = pixels.mutable_unchecked<2>();
        for (py::ssize_t i = 0; i < array.shape(0); ++i) {
          const Point p = project_point(camera, Eigen::Vector3d(in(i, 0), in(i, 1), in(i, 2)));
          out(i, 0) = p.x;
          out(i, 1) = p.y;
        }
        return pixels;
      },
      py::arg("points"), py::arg("intrinsics"), py::arg("distortion") = py::none(),
      "Pixels (N, 2) where camera-frame points (N, 3) are imaged, distortion applied.");
}

}  // namespace scbt
