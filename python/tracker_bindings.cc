// Python bindings of the tracker: Tracker (init, init_from_box, track), its per-frame FrameStats
// with the state and confidence, and BoundaryEvidence.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <mutex>
#include <opencv2/core/mat.hpp>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "bindings.h"
#include "convert.h"
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
      } else if (key == "similarity_exponent") {
        options.similarity_exponent = value.cast<double>();
      } else if (key == "shape_weight") {
        options.shape_weight = value.cast<double>();
      } else if (key == "max_segments") {
        options.max_segments = value.cast<int>();
      } else if (key == "seed_stride") {
        options.bdsp.seed_stride = value.cast<int>();
      } else if (key == "loss_handling") {
        options.loss.enabled = value.cast<bool>();
      } else if (key == "normalize_exposure") {
        options.exposure.normalize = value.cast<bool>();
      } else if (key == "adapt_to_blur") {
        options.blur.adapt = value.cast<bool>();
      } else if (key == "predict_motion") {
        options.predict_motion = value.cast<bool>();
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
  d["similarity_exponent"] = o.similarity_exponent;
  d["shape_weight"] = o.shape_weight;
  d["seed_stride"] = o.bdsp.seed_stride;
  d["loss_handling"] = o.loss.enabled;
  d["normalize_exposure"] = o.exposure.normalize;
  d["adapt_to_blur"] = o.blur.adapt;
  d["predict_motion"] = o.predict_motion;
  d["keep_debug"] = keep_debug;
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

std::string format_stats(const TrackResult& s) {
  char text[320];
  std::snprintf(text, sizeof(text),
                "FrameStats(state='%s', confidence=%.3f, held=%s, cost=%.6g, area_similarity=%.4f, "
                "num_detected=%d, "
                "num_kept=%d, num_vertices=%d, num_edges=%d, num_candidates=%d, line_ms=%.3f, "
                "grouping_ms=%.3f)",
                to_string(s.state).c_str(), s.confidence, s.held ? "True" : "False", s.cost,
                s.area_similarity, s.num_detected, s.num_kept, s.num_vertices, s.num_edges,
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
      "Tracker(**options) with keyword options (paper defaults):\n"
      "  detector='edlines' ('opencv-edlines', 'lsd', 'fld'), gradient_threshold=36,\n"
      "  anchor_threshold=8, scan_interval=1, sigma=1.0,\n"
      "  min_line_length=-1 (automatic), line_fit_error=1.0,\n"
      "  crop_to_boundary=True, roi_padding=8.0, filter_distance=20.0,\n"
      "  min_area_similarity=0.9, cost_tolerance=0.1, similarity_exponent=0.5,\n"
      "  shape_weight=4.0, max_segments=1500,\n"
      "  seed_stride=2, loss_handling=True, normalize_exposure=True, adapt_to_blur=True,\n"
      "  predict_motion=True, keep_debug=False.\n"
      "Raises ValueError naming a bad value, TypeError for an unknown option.")
      .def(py::init<const py::kwargs&>())
      .def("init", &PyTracker::init, py::arg("frame"), py::arg("polygon"),
           "Sets the initial boundary: `polygon` is an (N, 2) array inside `frame`.\n"
           "Raises ValueError for an unusable polygon (fewer than 3 distinct vertices, no area,\n"
           "self-crossing, outside the frame).")
      .def("init_from_box", &PyTracker::init_from_box, py::arg("frame"), py::arg("box"),
           "Initialises from a box (x, y, w, h) instead of a polygon: the most salient closed\n"
           "boundary inside it (the least-Γ cycle of the segments detected there) becomes the\n"
           "initial boundary and is returned as an (N, 2) array. Raises ValueError for a bad\n"
           "frame or box, RuntimeError when the box holds no closed boundary.")
      .def("track", &PyTracker::track, py::arg("frame"),
           "Tracks the boundary into `frame` (the GIL is released meanwhile).\n"
           "Returns (boundary, stats): an (N, 2) float64 array and a FrameStats. When no\n"
           "candidate is admissible the previous boundary is returned and stats.held is True;\n"
           "while stats.state is 'lost' it is the last confident boundary.")
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
}

}  // namespace scbt
