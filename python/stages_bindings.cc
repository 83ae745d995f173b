// Python bindings of the pipeline's stages one by one (paper §III): line detection, the
// distance filter, the segment graph, BDSP cycle candidates and the choice.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <set>
#include <string>
#include <vector>

#include "bindings.h"
#include "convert.h"
#include "scbt/choice/boundary_choice.h"
#include "scbt/cycles/bdsp.h"
#include "scbt/filter/segment_filter.h"
#include "scbt/graph/segment_graph.h"
#include "scbt/lines/line_detector.h"

namespace py = pybind11;

namespace scbt {
namespace {

// get(edge) of every edge of the graph as an (E,) array.
template <typename T, typename Get>
py::array_t<T> per_edge(const SegmentGraph& g, Get get) {
  py::array_t<T> a(static_cast<py::ssize_t>(g.edges.size()));
  for (size_t i = 0; i < g.edges.size(); ++i) a.mutable_at(i) = get(g.edges[i]);
  return a;
}

}  // namespace

void register_stages(py::module_& m) {
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
            return per_edge<bool>(g, [](const GraphEdge& e) { return e.detected; });
          },
          "(E,) bool array: True for detected segments, False for generated ones.")
      .def_property_readonly(
          "edge_weights",
          [](const SegmentGraph& g) {
            return per_edge<double>(g, [](const GraphEdge& e) { return e.weight; });
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
}

}  // namespace scbt
