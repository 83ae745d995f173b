// Conversions between numpy arrays and scbt's types, and keyword-option helpers, shared by the
// Python module's register_* files.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <opencv2/core/mat.hpp>
#include <set>
#include <string>
#include <vector>

#include "scbt/geometry/polygon.h"
#include "scbt/lines/line_detector.h"

namespace scbt {

// "(H, W, 3)" for error messages.
std::string shape_text(const pybind11::array& a);
std::string dtype_text(const pybind11::array& a);

// NaN and infinity reach no stage: CGAL's triangulation crashes on them, the measures go silent.
double finite_argument(double value, const char* what);
void check_finite_row(const double* values, int count, pybind11::ssize_t row, const char* what);

// A frame as a cv::Mat header over the numpy buffer. The array must outlive the Mat; when its
// rows are not compact (a column slice, a negative stride) a C-contiguous copy is made and
// returned through `keep`.
cv::Mat frame_to_mat(const pybind11::object& object, const char* what, pybind11::array* keep);

Polygon array_to_polygon(const pybind11::object& object, const char* what);
pybind11::array_t<double> polygon_to_array(const Polygon& polygon);
std::vector<Segment> array_to_segments(const pybind11::object& object, const char* what);
pybind11::array_t<double> segments_to_array(const std::vector<Segment>& segments);

// Reads keyword options into the detector options; consumed keys are added to `used`.
void apply_detector_kwargs(const pybind11::kwargs& kwargs, LineDetectorOptions* o,
                           std::set<std::string>* used);
// TypeError for the first keyword not in `used`.
void reject_unknown(const pybind11::kwargs& kwargs, const std::set<std::string>& used,
                    const char* function);

// Casting a keyword's value fails with pybind11's generic cast_error; name the option instead.
template <typename F>
void with_option_names(const pybind11::kwargs& kwargs, F&& body) {
  try {
    body();
  } catch (const pybind11::cast_error&) {
    std::string names;
    for (auto item : kwargs) {
      names += (names.empty() ? "" : ", ") + pybind11::str(item.first).cast<std::string>() + "=" +
               pybind11::repr(item.second).cast<std::string>();
    }
    throw pybind11::type_error("an option has a value of the wrong type among: " + names);
  }
}

}  // namespace scbt
