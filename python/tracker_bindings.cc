// Python bindings of the tracker: Tracker (init, init_from_box, track), its per-frame FrameStats
// with the state and confidence, and BoundaryEvidence.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <mutex>
#include <opencv2/core/mat.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "bindings.h"
#include "convert.h"
#include "options_bindings.h"
#include "readonly_record.h"
#include "scbt/render/annotate.h"
#include "scbt/tracker/tracker.h"

namespace py = pybind11;

namespace scbt {
namespace {

// (x, y, w, h) of numbers, rounded to whole pixels. TypeError for anything else; ValueError for
// another length, or naming the value as it was given when it is not finite or no pixel
// coordinate (outside the range of a C int).
cv::Rect box_from_object(const py::object& object) {
  static const char* const kNames[] = {"x", "y", "w", "h"};
  std::vector<py::object> items;
  try {
    items = object.cast<std::vector<py::object>>();
  } catch (const py::cast_error&) {
    throw py::type_error("box must be a sequence of 4 numbers (x, y, w, h)");
  }
  if (items.size() != 4) {
    throw py::value_error("box must have 4 values (x, y, w, h), got " +
                          std::to_string(items.size()));
  }
  int values[4];
  for (int i = 0; i < 4; ++i) {
    const std::string given = py::str(items[i]).cast<std::string>();
    const std::string what = std::string("box ") + kNames[i] + "=" + given;
    // An int too large for a double is out of range too.
    double pixels = std::numeric_limits<double>::max();
    try {
      const double value = items[i].cast<double>();
      if (!std::isfinite(value)) throw py::value_error(what + " is not finite");
      pixels = std::round(value);
    } catch (const py::cast_error&) {
      if (!py::isinstance<py::int_>(items[i])) {
        throw py::type_error("box must be a sequence of 4 numbers (x, y, w, h), got " + what);
      }
    }
    if (!(pixels >= std::numeric_limits<int>::min() && pixels <= std::numeric_limits<int>::max())) {
      throw py::value_error(what + " is out of range (pixels from " +
                            std::to_string(std::numeric_limits<int>::min()) + " to " +
                            std::to_string(std::numeric_limits<int>::max()) + ")");
    }
    values[i] = static_cast<int>(pixels);
  }
  return cv::Rect(values[0], values[1], values[2], values[3]);
}

// The Python-facing tracker: the C++ Tracker plus a lock, since track() runs without the GIL
// and two Python threads could otherwise call into the same tracker at once.
class PyTracker {
 public:
  PyTracker(const TrackerOptions& options, bool keep_debug)
      : tracker_(options), keep_debug_(keep_debug) {
    tracker_.set_keep_debug(keep_debug_);
  }

  // A box (x, y, w, h) is four numbers in a row; a polygon is (N, 2).
  py::array_t<double> init(const py::object& frame_object, const py::object& shape) {
    const py::array values = py::array::ensure(shape);
    if (values && values.ndim() == 1 && values.size() == 4)
      return init_from_box(frame_object, shape);
    py::array keep;
    const cv::Mat frame = frame_to_mat(frame_object, "frame", &keep);
    const Polygon polygon = array_to_polygon(shape, "polygon");
    {
      py::gil_scoped_release release;
      std::lock_guard<std::mutex> lock(mutex_);
      tracker_.init(frame, polygon);
    }
    return polygon_to_array(polygon);
  }

  py::array_t<double> init_from_box(const py::object& frame_object, const py::object& box_object) {
    py::array keep;
    const cv::Mat frame = frame_to_mat(frame_object, "frame", &keep);
    const cv::Rect box = box_from_object(box_object);
    Polygon boundary;
    {
      py::gil_scoped_release release;
      std::lock_guard<std::mutex> lock(mutex_);
      boundary = tracker_.init_from_box(frame, box);
    }
    return polygon_to_array(boundary);
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
    py::array_t<double> boundary = polygon_to_array(result.boundary);
    result.boundary.clear();  // FrameStats: the rest of the result
    return py::make_tuple(boundary, result);
  }

  // OpenCV's Tracker.update: whether the object was found in `frame`, and its boundary.
  py::tuple update(const py::object& frame_object) {
    const py::tuple tracked = track(frame_object);
    const TrackResult& stats = tracked[1].cast<const TrackResult&>();
    const bool found = !stats.held && stats.state != TrackState::kLost;
    return py::make_tuple(found, tracked[0]);
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
  TrackerOptions options() { return tracker_.options(); }
  bool keep_debug() const { return keep_debug_; }

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

std::string format_stats(const TrackResult& s) {
  char text[320];
  std::snprintf(text, sizeof(text),
                "FrameStats(state='%s', confidence=%.3f, visible=%.3f, held=%s, cost=%.6g, "
                "area_similarity=%.4f, "
                "num_detected=%d, "
                "num_kept=%d, num_vertices=%d, num_edges=%d, num_candidates=%d, line_ms=%.3f, "
                "grouping_ms=%.3f)",
                to_string(s.state).c_str(), s.confidence, s.visible, s.held ? "True" : "False",
                s.cost, s.area_similarity, s.num_detected, s.num_kept, s.num_vertices, s.num_edges,
                s.num_candidates, s.line_ms, s.grouping_ms);
  return text;
}

}  // namespace

void register_tracker(py::module_& m) {
  ReadonlyRecord<BoundaryEvidence>(
      m, "BoundaryEvidence", "What a frame's confidence was computed from (docs/loss-handling.md).")
      .field("gap_share", &BoundaryEvidence::gap_share,
             "Share of the boundary's length made of generated (gap-filling) segments.")
      .field("edge_support", &BoundaryEvidence::edge_support,
             "Share of points along the boundary with a grey step across it.")
      .field("shape_change", &BoundaryEvidence::shape_change,
             "Shape distance to the last confident boundary.")
      .field("jump", &BoundaryEvidence::jump,
             "Centroid displacement since the previous frame over sqrt(area).")
      .field("inside_level", &BoundaryEvidence::inside_level,
             "Mean grey level just inside the boundary (-1 unknown).")
      .with_as_dict("The evidence as a dict.")
      .def("__repr__", [](const BoundaryEvidence& e) {
        char text[200];
        std::snprintf(text, sizeof(text),
                      "BoundaryEvidence(gap_share=%.3f, edge_support=%.3f, shape_change=%.3f, "
                      "jump=%.3f, inside_level=%.1f)",
                      e.gap_share, e.edge_support, e.shape_change, e.jump, e.inside_level);
        return std::string(text);
      });

  // Tracker.track's statistics: the TrackResult without its boundary.
  ReadonlyRecord<TrackResult>(m, "FrameStats",
                              "Statistics and timings of one tracked frame (see Tracker.track).")
      .field("held", &TrackResult::held,
             "True when no candidate was admissible and the previous boundary was kept.")
      .field("cost", &TrackResult::cost, "Grouping cost Γ = |B_G| / area of the choice.")
      .field("area_similarity", &TrackResult::area_similarity,
             "Area similarity (Eq. 2) of the choice with the previous boundary.")
      .field("num_detected", &TrackResult::num_detected, "Segments the detector found.")
      .field("num_kept", &TrackResult::num_kept, "Segments passing the distance filter.")
      .field("num_dropped", &TrackResult::num_dropped,
             "Segments passing the filter but dropped by max_segments.")
      .field("num_vertices", &TrackResult::num_vertices, "Vertices of the segment graph.")
      .field("num_edges", &TrackResult::num_edges, "Edges of the segment graph.")
      .field("num_candidates", &TrackResult::num_candidates, "BDSP cycle candidates evaluated.")
      .field("recovered", &TrackResult::recovered,
             "True when the boundary was found again where image motion moved it.")
      .computed(
          "state", [](const TrackResult& r) { return to_string(r.state); },
          "'tracking', 'uncertain' or 'lost' (docs/loss-handling.md).")
      .field("confidence", &TrackResult::confidence,
             "How far to trust the boundary, in [0, 1]; 0 when held or lost.")
      .field("visible", &TrackResult::visible,
             "Fraction of the remembered outline whose edge was seen where the boundary puts it "
             "(1 before the memory holds an outline, 0 when held or lost).")
      .field("from_memory", &TrackResult::from_memory,
             "True when the boundary is the remembered outline fitted to the visible part of the "
             "object (the cycle found departed from it, or none was found).")
      .field("evidence", &TrackResult::evidence,
             "The BoundaryEvidence the confidence was computed from.")
      .field("reacquired", &TrackResult::reacquired,
             "True on the frame a lost object was found again.")
      .field("line_ms", &TrackResult::line_ms, "Colour conversion + line detection (ms).")
      .field("grouping_ms", &TrackResult::grouping_ms, "Filter + graph + BDSP + choice (ms).")
      .computed(
          "total_ms", [](const TrackResult& r) { return r.total_ms(); }, "line_ms + grouping_ms.")
      .with_as_dict("The statistics as a dict.")
      .def("__repr__", &format_stats);

  py::class_<PyTracker>(
      m, "Tracker",
      "The salient closed boundary tracker.\n\n"
      "Tracker(options=None, *, keep_debug=False, **options): `options` a TrackerOptions, the\n"
      "keyword arguments the same options by name (shape_weight=2.0, predict_motion=False, ...;\n"
      "help(scbt.TrackerOptions) lists them with their defaults and ranges); keyword arguments\n"
      "override `options`. keep_debug=True keeps the last frame's segments and graph\n"
      "(detected_segments(), graph()). Raises ValueError naming a bad value, TypeError for an\n"
      "unknown option or a value of the wrong type.\n\n"
      "    tracker = scbt.Tracker(shape_weight=2.0)\n"
      "    tracker.init(frame, (x, y, w, h))        # or an (N, 2) polygon\n"
      "    ok, boundary = tracker.update(next_frame)")
      .def(py::init([](const py::object& options, bool keep_debug, const py::kwargs& kwargs) {
             return std::make_unique<PyTracker>(options_from_python(options, kwargs, "Tracker", {}),
                                                keep_debug);
           }),
           py::arg("options") = py::none(), py::kw_only(), py::arg("keep_debug") = false)
      .def("init", &PyTracker::init, py::arg("frame"), py::arg("box_or_polygon"),
           "Starts tracking on `frame` from a box (x, y, w, h), whose most salient closed\n"
           "boundary is taken (as init_from_box), or from a polygon, an (N, 2) array inside the\n"
           "frame. Returns the initial boundary as an (N, 2) array. Raises ValueError for an\n"
           "unusable polygon or box (fewer than 3 distinct vertices, no area, self-crossing,\n"
           "outside the frame), RuntimeError when the box holds no closed boundary.")
      .def("init_from_box", &PyTracker::init_from_box, py::arg("frame"), py::arg("box"),
           "Initialises from a box (x, y, w, h): the most salient closed boundary inside it\n"
           "(the least-cost cycle of the segments detected there) becomes the initial boundary\n"
           "and is returned as an (N, 2) array. Raises ValueError for a bad frame or box,\n"
           "RuntimeError when the box holds no closed boundary.")
      .def("update", &PyTracker::update, py::arg("frame"),
           "Tracks the boundary into `frame`, as OpenCV's trackers' update(): returns\n"
           "(ok, boundary), ok False when nothing was found on this frame (the previous\n"
           "boundary held) or the object is lost, boundary an (N, 2) float64 array (while\n"
           "lost, the last confident one). track() returns the frame's statistics too.")
      .def("track", &PyTracker::track, py::arg("frame"),
           "Tracks the boundary into `frame` (the GIL is released meanwhile).\n"
           "Returns (boundary, stats): an (N, 2) float64 array and a FrameStats. When no\n"
           "candidate is admissible the previous boundary is returned and stats.held is True;\n"
           "while stats.state is 'lost' it is the last confident boundary.")
      .def_property_readonly("boundary", &PyTracker::boundary,
                             "The current boundary as an (N, 2) array, None before init().")
      .def_property_readonly("initialized", &PyTracker::initialized,
                             "True once init() has set a boundary.")
      .def_property_readonly("options", &PyTracker::options,
                             "The tracker's options, a TrackerOptions (options['name'] reads one).")
      .def_property_readonly("keep_debug", &PyTracker::keep_debug,
                             "Whether the last frame's segments and graph are kept.")
      .def("detected_segments", &PyTracker::detected_segments,
           "All segments detected in the last tracked frame, (M, 4) (needs keep_debug=True).")
      .def("graph", &PyTracker::debug_graph,
           "The last tracked frame's SegmentGraph (needs keep_debug=True).")
      .def("annotate", &PyTracker::annotate, py::arg("frame"), py::arg("status") = py::none(),
           "A BGR copy of `frame` with the last frame's segments and the boundary drawn as\n"
           "`scbt track --video` draws them.");
}

}  // namespace scbt
