// Micro-benchmarks of every tracking stage on inputs generated in code at the dataset's scale:
// 640x480 frames, 50-150 segments near a boundary. Run pinned to one core:
//   taskset -c 0 build/bench/scbt_stage_bench
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "bench_inputs.h"
#include "scbt/choice/boundary_choice.h"
#include "scbt/cycles/bdsp.h"
#include "scbt/filter/segment_filter.h"
#include "scbt/graph/segment_graph.h"
#include "scbt/lines/line_detector.h"
#include "scbt/reference/plain_choice.h"
#include "scbt/synthetic/scene.h"
#include "scbt/tracker/frame_checks.h"
#include "scbt/tracker/tracker.h"

namespace scbt {
namespace {

using bench_inputs::make_boundary;
using bench_inputs::make_segments;

SceneFrame make_frame() {
  SceneOptions options;
  options.shape = SceneShape::kBox;
  options.object_size = 120.0;
  return render_frame(options, Pose{}, 0);
}

void BM_ToGray(benchmark::State& state) {
  const cv::Mat frame = make_frame().image;
  cv::Mat gray;
  for (auto _ : state) {
    to_gray(frame, &gray);
    benchmark::DoNotOptimize(gray.data);
  }
}
BENCHMARK(BM_ToGray)->Unit(benchmark::kMicrosecond);

// Line detection on the whole frame (arg 0) or only on the window around the boundary (arg 1).
void BM_EdLines(benchmark::State& state) {
  const SceneFrame scene = make_frame();
  cv::Mat gray;
  to_gray(scene.image, &gray);
  LineDetectorOptions options;
  std::unique_ptr<LineDetector> detector = make_line_detector(options);
  const cv::Rect roi = state.range(0) == 0
                           ? cv::Rect(cv::Point(0, 0), gray.size())
                           : detection_roi(scene.truth, 20.0 + options.roi_padding, gray.size());
  size_t found = 0;
  for (auto _ : state) {
    const std::vector<Segment> segments = detector->detect_in(gray(roi), roi.tl(), gray.size());
    found = segments.size();
    benchmark::DoNotOptimize(segments.data());
  }
  state.counters["segments"] = static_cast<double>(found);
  state.counters["roi_share"] = roi.area() / static_cast<double>(gray.total());
}
BENCHMARK(BM_EdLines)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

void BM_Filter(benchmark::State& state) {
  const Polygon boundary = make_boundary();
  const std::vector<Segment> segments =
      make_segments(boundary, static_cast<int>(state.range(0)) * 3, 7);
  for (auto _ : state) {
    benchmark::DoNotOptimize(filter_segments_near_boundary(segments, boundary, 20.0));
  }
}
BENCHMARK(BM_Filter)->Arg(50)->Arg(100)->Arg(150)->Unit(benchmark::kMicrosecond);

void BM_SegmentGraph(benchmark::State& state) {
  const std::vector<Segment> segments =
      make_segments(make_boundary(), static_cast<int>(state.range(0)), 11);
  for (auto _ : state) benchmark::DoNotOptimize(build_segment_graph(segments));
}
BENCHMARK(BM_SegmentGraph)->Arg(50)->Arg(100)->Arg(150)->Unit(benchmark::kMicrosecond);

void BM_Bdsp(benchmark::State& state) {
  const SegmentGraph graph =
      build_segment_graph(make_segments(make_boundary(), static_cast<int>(state.range(0)), 13));
  size_t candidates = 0;
  for (auto _ : state) {
    const std::vector<CycleCandidate> found = search_cycle_candidates(graph);
    candidates = found.size();
    benchmark::DoNotOptimize(found.data());
  }
  state.counters["candidates"] = static_cast<double>(candidates);
  state.counters["vertices"] = graph.num_vertices();
}
BENCHMARK(BM_Bdsp)->Arg(50)->Arg(100)->Arg(150)->Unit(benchmark::kMicrosecond);

void BM_Choice(benchmark::State& state) {
  const Polygon boundary = make_boundary();
  const SegmentGraph graph =
      build_segment_graph(make_segments(boundary, static_cast<int>(state.range(0)), 17));
  const std::vector<CycleCandidate> candidates = search_cycle_candidates(graph);
  for (auto _ : state) {
    benchmark::DoNotOptimize(choose_boundary_stable(candidates, graph, boundary, 0.9, 0.1));
  }
}
BENCHMARK(BM_Choice)->Arg(50)->Arg(100)->Arg(150)->Unit(benchmark::kMicrosecond);

// The whole Tracker::track on a rendered frame, cropped (arg 1) or whole-frame (arg 0).
void BM_Track(benchmark::State& state) {
  const SceneFrame scene = make_frame();
  TrackerOptions options;
  options.detector.crop_to_boundary = state.range(0) != 0;
  Tracker tracker(options);
  for (auto _ : state) {
    state.PauseTiming();
    tracker.init(scene.image, scene.truth);
    state.ResumeTiming();
    benchmark::DoNotOptimize(tracker.track(scene.image));
  }
}
BENCHMARK(BM_Track)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace scbt

BENCHMARK_MAIN();
