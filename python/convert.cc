#include "convert.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace py = pybind11;

namespace scbt {

std::string shape_text(const py::array& a) {
  std::ostringstream text;
  text << '(';
  for (py::ssize_t i = 0; i < a.ndim(); ++i) text << (i ? ", " : "") << a.shape(i);
  if (a.ndim() == 1) text << ',';
  text << ')';
  return text.str();
}

std::string dtype_text(const py::array& a) { return py::str(a.dtype()).cast<std::string>(); }

double finite_argument(double value, const char* what) {
  if (!std::isfinite(value)) {
    throw py::value_error(std::string(what) + " must be finite, got " + std::to_string(value));
  }
  return value;
}

void check_finite_row(const double* values, int count, py::ssize_t row, const char* what) {
  for (int k = 0; k < count; ++k) {
    if (!std::isfinite(values[k])) {
      throw py::value_error(std::string(what) + " row " + std::to_string(row) + " is not finite (" +
                            std::to_string(values[k]) + ")");
    }
  }
}

// A frame as a cv::Mat header over the numpy buffer. The array must outlive the Mat; when its
// rows are not compact (a column slice, a negative stride) a C-contiguous copy is made and
// returned through `keep`.
cv::Mat frame_to_mat(const py::object& object, const char* what, py::array* keep) {
  if (!py::isinstance<py::array>(object)) {
    throw py::type_error(std::string(what) + " must be a numpy.ndarray of dtype uint8, got " +
                         py::str(py::type::of(object).attr("__name__")).cast<std::string>());
  }
  py::array array = py::reinterpret_borrow<py::array>(object);
  if (!array.dtype().is(py::dtype::of<uint8_t>())) {
    throw py::type_error(std::string(what) + " must have dtype uint8 (8-bit grey or BGR), got " +
                         dtype_text(array) + " with shape " + shape_text(array));
  }
  const py::ssize_t ndim = array.ndim();
  const bool shape_ok =
      ndim == 2 ||
      (ndim == 3 && (array.shape(2) == 1 || array.shape(2) == 3 || array.shape(2) == 4));
  if (!shape_ok) {
    throw py::value_error(std::string(what) +
                          " must have shape (H, W), (H, W, 1), (H, W, 3) or (H, W, 4), got " +
                          shape_text(array));
  }
  if (array.shape(0) == 0 || array.shape(1) == 0) {
    throw py::value_error(std::string(what) + " is empty: shape " + shape_text(array));
  }
  const int channels = ndim == 2 ? 1 : static_cast<int>(array.shape(2));
  const bool rows_compact =
      array.strides(0) > 0 && array.strides(1) == channels && (ndim == 2 || array.strides(2) == 1);
  if (!rows_compact) {
    array = py::array::ensure(array, py::array::c_style);
    if (!array) throw py::error_already_set();
  }
  *keep = array;
  const int rows = static_cast<int>(array.shape(0));
  const int cols = static_cast<int>(array.shape(1));
  // cv::Mat never writes through a header made for reading here; the cast only fits its API.
  return cv::Mat(rows, cols, CV_8UC(channels), const_cast<void*>(array.data()),
                 static_cast<size_t>(array.strides(0)));
}

namespace {

using DoubleRows = py::array_t<double, py::array::c_style | py::array::forcecast>;

// `object` (anything numpy converts) as rows of `columns` finite doubles. TypeError when it does
// not convert, ValueError for another shape or a row that is not finite; both name `what` and
// the `shape` expected ("(N, 2) array of x, y coordinates"). With `empty_ok`, an empty list
// (shape (0,)) is no rows.
DoubleRows finite_rows(const py::object& object, py::ssize_t columns, const char* what,
                       const std::string& shape, const std::string& content, bool empty_ok) {
  DoubleRows array;
  try {
    array = DoubleRows::ensure(object);
  } catch (const py::error_already_set&) {
  }
  if (!array) {
    PyErr_Clear();
    throw py::type_error(std::string(what) + " must be an " + shape + " array of " + content);
  }
  if (array.ndim() == 1 && array.shape(0) == 0 && empty_ok)
    return DoubleRows(std::vector<py::ssize_t>{0, columns});
  if (array.ndim() != 2 || array.shape(1) != columns) {
    throw py::value_error(std::string(what) + " must have shape " + shape + ", got " +
                          shape_text(array));
  }
  for (py::ssize_t i = 0; i < array.shape(0); ++i) {
    check_finite_row(array.data(i, 0), static_cast<int>(columns), i, what);
  }
  return array;
}

}  // namespace

Polygon array_to_polygon(const py::object& object, const char* what) {
  const DoubleRows array = finite_rows(object, 2, what, "(N, 2)", "x, y coordinates", false);
  Polygon polygon(static_cast<size_t>(array.shape(0)));
  auto view = array.unchecked<2>();
  for (py::ssize_t i = 0; i < array.shape(0); ++i) polygon[i] = Point(view(i, 0), view(i, 1));
  return polygon;
}

py::array_t<double> polygon_to_array(const Polygon& polygon) {
  py::array_t<double> array({static_cast<py::ssize_t>(polygon.size()), py::ssize_t{2}});
  auto view = array.mutable_unchecked<2>();
  for (size_t i = 0; i < polygon.size(); ++i) {
    view(i, 0) = polygon[i].x;
    view(i, 1) = polygon[i].y;
  }
  return array;
}

std::vector<Segment> array_to_segments(const py::object& object, const char* what) {
  const DoubleRows array = finite_rows(object, 4, what, "(M, 4)", "x1, y1, x2, y2 rows", true);
  std::vector<Segment> segments(static_cast<size_t>(array.shape(0)));
  auto view = array.unchecked<2>();
  for (py::ssize_t i = 0; i < array.shape(0); ++i) {
    segments[i] = Segment{Point(view(i, 0), view(i, 1)), Point(view(i, 2), view(i, 3))};
  }
  return segments;
}

py::array_t<double> segments_to_array(const std::vector<Segment>& segments) {
  py::array_t<double> array({static_cast<py::ssize_t>(segments.size()), py::ssize_t{4}});
  auto view = array.mutable_unchecked<2>();
  for (size_t i = 0; i < segments.size(); ++i) {
    view(i, 0) = segments[i].a.x;
    view(i, 1) = segments[i].a.y;
    view(i, 2) = segments[i].b.x;
    view(i, 3) = segments[i].b.y;
  }
  return array;
}

// Reads keyword options into the detector options; consumed keys are added to `used`.
void apply_detector_kwargs(const py::kwargs& kwargs, LineDetectorOptions* o,
                           std::set<std::string>* used) {
  for (auto item : kwargs) {
    const std::string key = py::str(item.first).cast<std::string>();
    const py::handle value = item.second;
    bool known = true;
    if (key == "detector") {
      o->kind = parse_line_detector_kind(value.cast<std::string>());
    } else if (key == "gradient_threshold") {
      o->gradient_threshold = value.cast<int>();
    } else if (key == "anchor_threshold") {
      o->anchor_threshold = value.cast<int>();
    } else if (key == "scan_interval") {
      o->scan_interval = value.cast<int>();
    } else if (key == "sigma") {
      o->sigma = value.cast<double>();
    } else if (key == "min_line_length") {
      o->min_line_length = value.cast<double>();
    } else if (key == "line_fit_error") {
      o->line_fit_error = value.cast<double>();
    } else if (key == "crop_to_boundary") {
      o->crop_to_boundary = value.cast<bool>();
    } else if (key == "roi_padding") {
      o->roi_padding = value.cast<double>();
    } else {
      known = false;
    }
    if (known) used->insert(key);
  }
}

void reject_unknown(const py::kwargs& kwargs, const std::set<std::string>& used,
                    const char* function) {
  for (auto item : kwargs) {
    const std::string key = py::str(item.first).cast<std::string>();
    if (!used.count(key)) {
      throw py::type_error(std::string(function) + "() got an unexpected keyword argument '" + key +
                           "'");
    }
  }
}

}  // namespace scbt
