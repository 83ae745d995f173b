// The `scbt` Python module: the salient closed boundary tracker, its stages and the E_AL metric.
// Frames are numpy uint8 arrays as OpenCV's Python bindings give them, wrapped in cv::Mat headers
// without copying whenever their rows are compact; polygons and segments are float64 arrays.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstring>
#include <mutex>
#include <opencv2/core/mat.hpp>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "depth_bindings.h"
#include "scbt/choice/boundary_choice.h"
#include "scbt/cycles/bdsp.h"
#include "scbt/eval/alignment_error.h"
#include "scbt/filter/segment_filter.h"
#include "scbt/geometry/polygon.h"
#include "scbt/geometry/polygon_io.h"
#include "scbt/graph/segment_graph.h"
#include "scbt/lines/line_detector.h"
#include "scbt/render/annotate.h"
#include "scbt/tracker/tracker.h"
#include "scbt/version.h"

namespace py = pybind11;

namespace scbt {
namespace {

std::string shape_text(const py::array& a) {
  std::ostringstream text;
  text << '(';
  for (py::ssize_t i = 0; i < a.ndim(); ++i) text << (i ? ", " : "") << a.shape(i);
  if (a.ndim() == 1) text << ',';
  text << ')';
  return text.str();
}

std::string dtype_text(const py::array& a) { return py::str(a.dtype()).cast<std::string>(); }

// NaN and infinity reach no stage: CGAL's triangulation crashes on them, the measures go silent.
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

Polygon array_to_polygon(const py::object& object, const char* what) {
  py::array_t<double, py::array::c_style | py::array::forcecast> array;
  try {
    array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(object);
  } catch (const py::error_already_set&) {
  }
  if (!array) {
    PyErr_Clear();
    throw py::type_error(std::string(what) + " must be an (N, 2) array of x, y coordinates");
  }
  if (array.ndim() != 2 || array.shape(1) != 2) {
    throw py::value_error(std::string(what) + " must have shape (N, 2), got " + shape_text(array));
  }
  Polygon polygon(static_cast<size_t>(array.shape(0)));
  auto view = array.unchecked<2>();
  for (py::ssize_t i = 0; i < array.shape(0); ++i) {
    const double row[2] = {view(i, 0), view(i, 1)};
    check_finite_row(row, 2, i, what);
    polygon[i] = Point(row[0], row[1]);
  }
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
  py::array_t<double, py::array::c_style | py::array::forcecast> array;
  try {
    array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(object);
  } catch (const py::error_already_set&) {
  }
  if (!array) {
    PyErr_Clear();
    throw py::type_error(std::string(what) + " must be an (M, 4) array of x1, y1, x2, y2 rows");
  }
  if (array.ndim() != 2 || array.shape(1) != 4) {
    // An empty list arrives as shape (0,); accept it as no segments.
    if (array.ndim() == 1 && array.shape(0) == 0) return {};
    throw py::value_error(std::string(what) + " must have shape (M, 4), got " + shape_text(array));
  }
  std::vector<Segment> segments(static_cast<size_t>(array.shape(0)));
  auto view = array.unchecked<2>();
  for (py::ssize_t i = 0; i < array.shape(0); ++i) {
    const double row[4] = {view(i, 0), view(i, 1), view(i, 2), view(i, 3)};
    check_finite_row(row, 4, i, what);
    segments[i] = Segment{Point(row[0], row[1]), Point(row[2], row[3])};
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

// Casting a keyword's value fails with pybind11's generic cast_error; name the option instead.
template <typename F>
void with_option_names(const py::kwargs& kwargs, F&& body) {
  try {
    body();
  } catch (const py::cast_error&) {
    std::string names;
    for (auto item : kwargs) {
      names += (names.empty() ? "" : ", ") + py::str(item.first).cast<std::string>() + "=" +
               py::repr(item.second).cast<std::string>();
    }
    throw py::type_error("an option has a value of the wrong type among: " + names);
  }
}

TrackerOptions tracker_options_from_kwargs(const py::kwargs& kwargs, bool* keep_debug) {
  TrackerOptions options;
  std::set<std::string> used;
  with_option_names(kwargs, [&] {
    apply_detector_kwargs(kwargs, &options.detector, &used);
    for (auto item : kwargs) {
      const std::string key = py::str(item.first).cast<std::string>();
      const py::handle value = item.second;
      bool known = true;
      if (key == "filter_distance") {
        options.filter_distance = value.cast<double>();
      } else if (key == "min_area_similarity") {
        options.min_area_similarity = value.cast<double>();
      } else if (key == "cost_tolerance") {
        options.cost_tolerance = value.cast<double>();
      } else if (key == "max_segments") {
        options.max_segments = value.cast<int>();
      } else if (key == "seed_stride") {
        options.bdsp.seed_stride = value.cast<int>();
      } else if (key == "keep_debug") {
        *keep_debug = value.cast<bool>();
      } else {
        known = false;
      }
      if (known) used.insert(key);
    }
  });
  reject_unknown(kwargs, used, "Tracker");
  return options;
}

py::dict options_to_dict(const TrackerOptions& o, bool keep_debug) {
  py::dict d;
  d["detector"] = to_string(o.detector.kind);
  d["gradient_threshold"] = o.detector.gradient_threshold;
  d["anchor_threshold"] = o.detector.anchor_threshold;
  d["scan_interval"] = o.detector.scan_interval;
  d["sigma"] = o.detector.sigma;
  d["min_line_length"] = o.detector.min_line_length;
  d["line_fit_error"] = o.detector.line_fit_error;
  d["crop_to_boundary"] = o.detector.crop_to_boundary;
  d["roi_padding"] = o.detector.roi_padding;
  d["max_segments"] = o.max_segments;
  d["filter_distance"] = o.filter_distance;
  d["min_area_similarity"] = o.min_area_similarity;
  d["cost_tolerance"] = o.cost_tolerance;
  d["seed_stride"] = o.bdsp.seed_stride;
  d["keep_debug"] = keep_debug;
  return d;
}

// Per-frame statistics of Tracker.track (TrackResult without the boundary).
struct FrameStats {
  bool held = false;
  double cost = 0.0;
  double area_similarity = 0.0;
  int num_detected = 0;
  int num_kept = 0;
  int num_dropped = 0;
  int num_vertices = 0;
  int num_edges = 0;
  int num_candidates = 0;
  double line_ms = 0.0;
  double grouping_ms = 0.0;
  double total_ms() const { return line_ms + grouping_ms; }
};

FrameStats stats_of(const TrackResult& r) {
  FrameStats s;
  s.held = r.held;
  s.cost = r.cost;
  s.area_similarity = r.area_similarity;
  s.num_detected = r.num_detected;
  s.num_kept = r.num_kept;
  s.num_dropped = r.num_dropped;
  s.num_vertices = r.num_vertices;
  s.num_edges = r.num_edges;
  s.num_candidates = r.num_candidates;
  s.line_ms = r.line_ms;
  s.grouping_ms = r.grouping_ms;
  return s;
}

py::dict stats_to_dict(const FrameStats& s) {
  py::dict d;
  d["held"] = s.held;
  d["cost"] = s.cost;
  d["area_similarity"] = s.area_similarity;
  d["num_detected"] = s.num_detected;
  d["num_kept"] = s.num_kept;
  d["num_dropped"] = s.num_dropped;
  d["num_vertices"] = s.num_vertices;
  d["num_edges"] = s.num_edges;
  d["num_candidates"] = s.num_candidates;
  d["line_ms"] = s.line_ms;
  d["grouping_ms"] = s.grouping_ms;
  d["total_ms"] = s.total_ms();
  return d;
}

// The Python-facing tracker: the C++ Tracker plus a lock, since track() runs without the GIL
// and two Python threads could otherwise call into the same tracker at once.
class PyTracker {
 public:
  explicit PyTracker(const py::kwargs& kwargs) {
    const TrackerOptions options = tracker_options_from_kwargs(kwargs, &keep_debug_);
    tracker_ = Tracker(options);
    tracker_.set_keep_debug(keep_debug_);
  }

  void init(const py::object& frame_object, const py::object& polygon_object) {
    py::array keep;
    const cv::Mat frame = frame_to_mat(frame_object, "frame", &keep);
    const Polygon polygon = array_to_polygon(polygon_object, "polygon");
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(mutex_);
    tracker_.init(frame, polygon);
  }

  py::tuple track(const py::object& frame_object) {
    py::array keep;
    const cv::Mat frame = frame_to_mat(frame_object, "frame", &keep);
    TrackResult result;
    {
      py::gil_scoped_release release;
      std::lock_guard<std::mutex> lock(mutex_);
      if (!tracker_.initialized()) {
        throw std::logic_error("Tracker.track() called before Tracker.init()");
      }
      result = tracker_.track(frame);
    }
    return py::make_tuple(polygon_to_array(result.boundary), stats_of(result));
  }

  py::object boundary() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!tracker_.initialized()) return py::none();
    return polygon_to_array(tracker_.boundary());
  }
  bool initialized() {
    std::lock_guard<std::mutex> lock(mutex_);
    return tracker_.initialized();
  }
  py::dict options() { return options_to_dict(tracker_.options(), keep_debug_); }

  py::array_t<double> detected_segments() {
    std::lock_guard<std::mutex> lock(mutex_);
    require_debug();
    return segments_to_array(tracker_.debug().detected);
  }
  SegmentGraph debug_graph() {
    std::lock_guard<std::mutex> lock(mutex_);
    require_debug();
    return tracker_.debug().graph;
  }

  py::array_t<uint8_t> annotate(const py::object& frame_object, const py::object& status) {
    py::array keep;
    const cv::Mat frame = frame_to_mat(frame_object, "frame", &keep);
    std::lock_guard<std::mutex> lock(mutex_);
    TrackResult result;
    result.boundary = tracker_.boundary();
    const cv::Mat out = annotate_frame(frame, tracker_.debug(), result,
                                       status.is_none() ? "" : status.cast<std::string>());
    py::array_t<uint8_t> array(
        {static_cast<py::ssize_t>(out.rows), static_cast<py::ssize_t>(out.cols), py::ssize_t{3}});
    for (int y = 0; y < out.rows; ++y) {
      std::memcpy(array.mutable_data(y), out.ptr(y), static_cast<size_t>(out.cols) * 3);
    }
    return array;
  }

 private:
  void require_debug() const {
    if (!keep_debug_) {
      throw std::logic_error(
          "create the Tracker with keep_debug=True to read the last frame's "
          "segments and graph");
    }
  }

  Tracker tracker_;
  bool keep_debug_ = false;
  std::mutex mutex_;
};

std::string format_stats(const FrameStats& s) {
  char text[256];
  std::snprintf(text, sizeof(text),
                "FrameStats(held=%s, cost=%.6g, area_similarity=%.4f, num_detected=%d, "
                "num_kept=%d, num_vertices=%d, num_edges=%d, num_candidates=%d, line_ms=%.3f, "
                "grouping_ms=%.3f)",
                s.held ? "True" : "False", s.cost, s.area_similarity, s.num_detected, s.num_kept,
                s.num_vertices, s.num_edges, s.num_candidates, s.line_ms, s.grouping_ms);
  return text;
}

}  // namespace
}  // namespace scbt

PYBIND11_MODULE(scbt, m) {
  using namespace scbt;
  m.doc() =
      "Real-time salient closed boundary tracking via line segment perceptual grouping "
      "(Qin et al., IROS 2017).\n\n"
      "Frames are numpy uint8 arrays of shape (H, W), (H, W, 1), (H, W, 3) (BGR) or (H, W, 4) "
      "(BGRA), as cv2 returns them; they are read in place when their rows are compact. "
      "Polygons are (N, 2) float arrays of x, y pixel coordinates; segments are (M, 4) float "
      "arrays of x1, y1, x2, y2. Bad options raise ValueError, wrong types TypeError.";
  m.attr("__version__") = SCBT_VERSION;

  py::class_<FrameStats>(m, "FrameStats",
                         "Statistics and timings of one tracked frame (see Tracker.track).")
      .def_readonly("held", &FrameStats::held,
                    "True when no candidate was admissible and the previous boundary was kept.")
      .def_readonly("cost", &FrameStats::cost, "Grouping cost Γ = |B_G| / area of the choice.")
      .def_readonly("area_similarity", &FrameStats::area_similarity,
                    "Area similarity (Eq. 2) of the choice with the previous boundary.")
      .def_readonly("num_detected", &FrameStats::num_detected, "Segments the detector found.")
      .def_readonly("num_kept", &FrameStats::num_kept, "Segments passing the distance filter.")
      .def_readonly("num_dropped", &FrameStats::num_dropped,
                    "Segments passing the filter but dropped by max_segments.")
      .def_readonly("num_vertices", &FrameStats::num_vertices, "Vertices of the segment graph.")
      .def_readonly("num_edges", &FrameStats::num_edges, "Edges of the segment graph.")
      .def_readonly("num_candidates", &FrameStats::num_candidates,
                    "BDSP cycle candidates evaluated.")
      .def_readonly("line_ms", &FrameStats::line_ms, "Colour conversion + line detection (ms).")
      .def_readonly("grouping_ms", &FrameStats::grouping_ms, "Filter + graph + BDSP + choice (ms).")
      .def_property_readonly("total_ms", &FrameStats::total_ms, "line_ms + grouping_ms.")
      .def("as_dict", &stats_to_dict, "The statistics as a dict.")
      .def("__repr__", &format_stats);

  py::class_<SegmentGraph>(m, "SegmentGraph",
                           "The weighted graph of detected and generated (gap-filling) segments.")
      .def_property_readonly(
          "vertices", [](const SegmentGraph& g) { return polygon_to_array(g.vertices); },
          "(V, 2) float array: segment endpoints.")
      .def_property_readonly(
          "edges",
          [](const SegmentGraph& g) {
            py::array_t<int> a({static_cast<py::ssize_t>(g.edges.size()), py::ssize_t{2}});
            auto v = a.mutable_unchecked<2>();
            for (size_t i = 0; i < g.edges.size(); ++i) {
              v(i, 0) = g.edges[i].u;
              v(i, 1) = g.edges[i].v;
            }
            return a;
          },
          "(E, 2) int array: vertex ids of each edge.")
      .def_property_readonly(
          "edge_detected",
          [](const SegmentGraph& g) {
            py::array_t<bool> a(static_cast<py::ssize_t>(g.edges.size()));
            for (size_t i = 0; i < g.edges.size(); ++i) a.mutable_at(i) = g.edges[i].detected;
            return a;
          },
          "(E,) bool array: True for detected segments, False for generated ones.")
      .def_property_readonly(
          "edge_weights",
          [](const SegmentGraph& g) {
            py::array_t<double> a(static_cast<py::ssize_t>(g.edges.size()));
            for (size_t i = 0; i < g.edges.size(); ++i) a.mutable_at(i) = g.edges[i].weight;
            return a;
          },
          "(E,) float array: Eq. 3 weights (0 for detected edges, length for generated ones).")
      .def_property_readonly("num_vertices", &SegmentGraph::num_vertices)
      .def_property_readonly("num_edges", &SegmentGraph::num_edges)
      .def(
          "segments",
          [](const SegmentGraph& g, bool detected_only) {
            std::vector<Segment> s;
            for (const GraphEdge& e : g.edges) {
              if (detected_only && !e.detected) continue;
              s.push_back(Segment{g.vertices[e.u], g.vertices[e.v]});
            }
            return segments_to_array(s);
          },
          py::arg("detected_only") = false,
          "The edges as an (E, 4) segment array (only the detected ones if asked).")
      .def("__repr__", [](const SegmentGraph& g) {
        return "SegmentGraph(num_vertices=" + std::to_string(g.num_vertices()) +
               ", num_edges=" + std::to_string(g.num_edges()) + ")";
      });

  py::class_<CycleCandidate>(m, "CycleCandidate", "A closed cycle found by the BDSP search.")
      .def_readonly("vertices", &CycleCandidate::vertices, "Graph vertex ids in cycle order.")
      .def_readonly("gap_length", &CycleCandidate::gap_length,
                    "|B_G|: total length of generated edges on the cycle.")
      .def_readonly("area", &CycleCandidate::area, "Enclosed area.")
      .def_readonly("seed_edge", &CycleCandidate::seed_edge, "The detected edge it grew from.")
      .def("__repr__", [](const CycleCandidate& c) {
        return "CycleCandidate(len=" + std::to_string(c.vertices.size()) +
               ", gap_length=" + std::to_string(c.gap_length) + ", area=" + std::to_string(c.area) +
               ")";
      });

  py::class_<BoundaryChoice>(m, "BoundaryChoice", "The candidate chosen by choose_boundary.")
      .def_readonly("index", &BoundaryChoice::index, "Index into the candidate list.")
      .def_readonly("cost", &BoundaryChoice::cost, "Grouping cost Γ of the chosen candidate.")
      .def_readonly("similarity", &BoundaryChoice::similarity, "Its area similarity.")
      .def_readonly("num_admissible", &BoundaryChoice::num_admissible,
                    "Candidates that passed the similarity gate.");

  py::class_<PyTracker>(
      m, "Tracker",
      "The salient closed boundary tracker.\n\n"
      "Tracker(**options) with keyword options (paper defaults):\n"
      "  detector='edlines' ('opencv-edlines', 'lsd', 'fld'), gradient_threshold=36,\n"
      "  anchor_threshold=8, scan_interval=1, sigma=1.0,\n"
      "  min_line_length=-1 (automatic), line_fit_error=1.0,\n"
      "  crop_to_boundary=True, roi_padding=8.0, filter_distance=20.0,\n"
      "  min_area_similarity=0.9, cost_tolerance=0.1, max_segments=1500,\n"
      "  seed_stride=2, keep_debug=False.\n"
      "Raises ValueError naming a bad value, TypeError for an unknown option.")
      .def(py::init<const py::kwargs&>())
      .def("init", &PyTracker::init, py::arg("frame"), py::arg("polygon"),
           "Sets the initial boundary: `polygon` is an (N, 2) array inside `frame`.\n"
           "Raises ValueError for an unusable polygon (fewer than 3 distinct vertices, no area,\n"
           "self-crossing, outside the frame).")
      .def("track", &PyTracker::track, py::arg("frame"),
           "Tracks the boundary into `frame` (the GIL is released meanwhile).\n"
           "Returns (boundary, stats): an (N, 2) float64 array and a FrameStats. When no\n"
           "candidate is admissible the previous boundary is returned and stats.held is True.")
      .def_property_readonly("boundary", &PyTracker::boundary,
                             "The current boundary as an (N, 2) array, None before init().")
      .def_property_readonly("initialized", &PyTracker::initialized)
      .def_property_readonly("options", &PyTracker::options, "The options as a dict.")
      .def("detected_segments", &PyTracker::detected_segments,
           "All segments detected in the last tracked frame, (M, 4) (needs keep_debug=True).")
      .def("graph", &PyTracker::debug_graph,
           "The last tracked frame's SegmentGraph (needs keep_debug=True).")
      .def("annotate", &PyTracker::annotate, py::arg("frame"), py::arg("status") = py::none(),
           "A BGR copy of `frame` with the last frame's segments and the boundary drawn as\n"
           "`scbt track --video` draws them.");

  m.def(
      "detect_line_segments",
      [](const py::object& image, const py::kwargs& kwargs) {
        LineDetectorOptions options;
        std::set<std::string> used;
        with_option_names(kwargs, [&] { apply_detector_kwargs(kwargs, &options, &used); });
        reject_unknown(kwargs, used, "detect_line_segments");
        options.check();
        py::array keep;
        const cv::Mat mat = frame_to_mat(image, "image", &keep);
        std::vector<Segment> segments;
        {
          py::gil_scoped_release release;
          segments = detect_line_segments(mat, options);
        }
        return segments_to_array(segments);
      },
      py::arg("image"),
      "Stage 1: line segments of an 8-bit grey/BGR image as an (M, 4) array.\n"
      "Keyword options: detector, gradient_threshold, anchor_threshold, scan_interval, sigma,\n"
      "min_line_length, line_fit_error (as for Tracker).");

  m.def(
      "filter_segments_near_boundary",
      [](const py::object& segments, const py::object& boundary, double max_mean_distance) {
        return segments_to_array(filter_segments_near_boundary(
            array_to_segments(segments, "segments"), array_to_polygon(boundary, "boundary"),
            finite_argument(max_mean_distance, "max_mean_distance")));
      },
      py::arg("segments"), py::arg("boundary"), py::arg("max_mean_distance") = 20.0,
      "Stage 2: the segments whose endpoints' and midpoint's mean distance to the closed\n"
      "boundary is below max_mean_distance, in input order.");

  m.def(
      "build_segment_graph",
      [](const py::object& segments) {
        return build_segment_graph(array_to_segments(segments, "segments"));
      },
      py::arg("segments"),
      "Stages 3-4: Delaunay gap filling and the weighted graph of an (M, 4) segment array.");

  m.def(
      "search_cycle_candidates",
      [](const SegmentGraph& graph, int seed_stride) {
        BdspOptions options;
        options.seed_stride = seed_stride;
        if (seed_stride < 1) {
          throw py::value_error("seed_stride must be >= 1, got " + std::to_string(seed_stride));
        }
        py::gil_scoped_release release;
        return search_cycle_candidates(graph, options);
      },
      py::arg("graph"), py::arg("seed_stride") = 2,
      "Stage 5: bidirectional shortest path cycle candidates of a SegmentGraph.");

  m.def(
      "candidate_polygon",
      [](const SegmentGraph& graph, const CycleCandidate& candidate) {
        for (int v : candidate.vertices) {
          if (v < 0 || v >= graph.num_vertices()) {
            throw py::value_error("candidate vertex " + std::to_string(v) + " is not in the graph");
          }
        }
        return polygon_to_array(candidate_polygon(graph, candidate));
      },
      py::arg("graph"), py::arg("candidate"), "The (N, 2) polygon of a cycle candidate.");

  m.def(
      "grouping_cost",
      [](double gap_length, double area) {
        return grouping_cost(finite_argument(gap_length, "gap_length"),
                             finite_argument(area, "area"));
      },
      py::arg("gap_length"), py::arg("area"),
      "Eq. 1: Γ = gap_length / area (infinite without area).");
  m.def(
      "area_similarity",
      [](double previous_area, double candidate_area) {
        return area_similarity(finite_argument(previous_area, "previous_area"),
                               finite_argument(candidate_area, "candidate_area"));
      },
      py::arg("previous_area"), py::arg("candidate_area"),
      "Eq. 2: min(A_p / A_c, A_c / A_p), 0 when either area is 0.");
  m.def(
      "choose_boundary",
      [](const std::vector<CycleCandidate>& candidates, double previous_area,
         double min_similarity) {
        return choose_boundary(candidates, finite_argument(previous_area, "previous_area"),
                               finite_argument(min_similarity, "min_similarity"));
      },
      py::arg("candidates"), py::arg("previous_area"), py::arg("min_similarity") = 0.9,
      "Stage 6 (paper rule): the admissible candidate (similarity > min_similarity) of least\n"
      "grouping cost, or None.");

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

  register_depth(m);
}
