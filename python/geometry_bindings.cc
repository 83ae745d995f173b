// Python bindings of the geometry and the metric: polygon area and checks, the shape descriptor
// distance, and the paper's alignment error E_AL.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bindings.h"
#include "convert.h"
#include "scbt/eval/alignment_error.h"
#include "scbt/geometry/polygon.h"
#include "scbt/geometry/polygon_io.h"
#include "scbt/geometry/shape_descriptor.h"

namespace py = pybind11;

namespace scbt {

void register_geometry(py::module_& m) {
  m.def(
      "read_polygons",
      [](const std::string& path) {
        std::vector<std::string> lines;
        try {
          lines = read_text_lines(path);
        } catch (const std::runtime_error& e) {
          throw py::value_error(e.what());
        }
        py::list polygons;
        for (size_t i = 0; i < lines.size(); ++i) {
          if (lines[i].find_first_not_of(" \t") == std::string::npos) continue;
          Polygon polygon;
          std::string error;
          if (!try_parse_polygon_line(lines[i], &polygon, &error)) {
            throw py::value_error(path + ":" + std::to_string(i + 1) + ": " + error);
          }
          polygons.append(polygon_to_array(polygon));
        }
        return polygons;
      },
      py::arg("path"),
      "The polygons of a results or ground-truth file, one per line (\"n x1 y1 ... xn yn\"),\n"
      "as a list of (N, 2) float64 arrays; blank lines are skipped. Raises ValueError naming\n"
      "the file and line of a malformed one.");
  m.def(
      "write_polygons",
      [](const std::string& path, const py::iterable& polygons) {
        std::string text;
        for (const py::handle& item : polygons) {
          text += format_polygon_line(
                      array_to_polygon(py::reinterpret_borrow<py::object>(item), "polygon")) +
                  "\n";
        }
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        if (!(out << text) || !out.flush()) {
          throw py::value_error(path + ": cannot write");
        }
      },
      py::arg("path"), py::arg("polygons"),
      "Writes (N, 2) polygons one per line in the format `scbt track -o` writes and\n"
      "read_polygons() reads (two decimals).");
  m.def(
      "alignment_error",
      [](const py::object& tracked, const py::object& truth, py::tuple canvas_size) {
        if (canvas_size.size() != 2) {
          throw py::value_error("canvas_size must be (width, height)");
        }
        const int width = canvas_size[0].cast<int>();
        const int height = canvas_size[1].cast<int>();
        if (width <= 0 || height <= 0) {
          throw py::value_error("canvas_size must be positive, got (" + std::to_string(width) +
                                ", " + std::to_string(height) + ")");
        }
        return alignment_error(array_to_polygon(tracked, "tracked"),
                               array_to_polygon(truth, "truth"), cv::Size(width, height));
      },
      py::arg("tracked"), py::arg("truth"), py::arg("canvas_size"),
      "The paper's alignment error E_AL (§IV-A) in pixels between two (N, 2) boundaries drawn\n"
      "on a canvas of canvas_size = (width, height); inf when either is degenerate (fewer than\n"
      "3 distinct points, no area); ValueError for NaN or infinite coordinates.");

  m.def(
      "area", [](const py::object& polygon) { return area(array_to_polygon(polygon, "polygon")); },
      py::arg("polygon"), "Area enclosed by a closed (N, 2) polygon.");
  m.def(
      "check_boundary_polygon",
      [](const py::object& polygon) {
        check_boundary_polygon(array_to_polygon(polygon, "polygon"));
      },
      py::arg("polygon"),
      "Raises ValueError unless the polygon can serve as a boundary (finite, >= 3 distinct\n"
      "vertices, non-zero area, not self-crossing).");
  m.def(
      "shape_distance",
      [](const py::object& a, const py::object& b) {
        return shape_distance(shape_descriptor(array_to_polygon(a, "a")),
                              shape_descriptor(array_to_polygon(b, "b")));
      },
      py::arg("a"), py::arg("b"),
      "Distance between the shapes of two closed (N, 2) polygons, independent of position,\n"
      "scale, rotation and vertex order (centroid-distance Fourier magnitudes): 0 for the same\n"
      "shape, 0.024 for a circle against an ellipse of aspect 1.1; inf without area.");
}

}  // namespace scbt
