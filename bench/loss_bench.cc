// What loss handling adds to a normally tracked frame: the evidence of the chosen boundary
// (confidence.h: gap share, edge samples, shape descriptor, jump), the confidence, and the state
// update that records a confident boundary (track_state.h), and the keyframe kept for the search
// (scene_keyframes.h); and, apart, what a frame costs while the object is lost. Run pinned to one
// core:
//   taskset -c 0 build/bench/scbt_loss_bench
#include <benchmark/benchmark.h>

#include <opencv2/imgproc.hpp>

#include "scbt/synthetic/scene.h"
#include "scbt/tracker/confidence.h"
#include "scbt/tracker/frame_checks.h"
#include "scbt/tracker/scene_keyframes.h"
#include "scbt/tracker/track_state.h"
#include "scbt/tracker/tracker.h"

namespace scbt {
namespace {

// A rim (72 vertices) or box outline on a rendered 640x480 frame, as a tracked boundary.
struct Input {
  Polygon boundary;
  Polygon previous;
  cv::Mat gray;
};

Input make_input(SceneShape shape) {
  SceneOptions options;
  options.shape = shape;
  options.object_size = 120.0;
  const SceneFrame frame = render_frame(options, Pose{}, 0);
  Input input;
  input.boundary = frame.truth;
  input.previous = frame.truth;
  for (Point& p : input.previous) p += Point(1.5, -0.5);
  to_gray(frame.image, &input.gray);
  return input;
}

void BM_ConfidenceAndState(benchmark::State& state) {
  const Input input = make_input(state.range(0) == 0 ? SceneShape::kRim : SceneShape::kBox);
  const ConfidenceModel model;
  LossMonitor monitor;
  monitor.reset(input.previous, -1.0);
  for (auto _ : state) {
    const BoundaryEvidence evidence = measure_evidence(
        input.boundary, 10.0, input.previous, monitor.reference(), input.gray, {0, 0}, 9.0);
    const double confidence = model(evidence);
    benchmark::DoNotOptimize(monitor.update(input.boundary, confidence, false, evidence));
  }
}
BENCHMARK(BM_ConfidenceAndState)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// SceneKeyframes::offer, called on every `tracking` frame: a count, and a grey copy of the whole
// 640x480 BGR frame on every keep_every-th call. The mean per call is what a normal frame pays.
void BM_KeyframeOffer(benchmark::State& state) {
  SceneOptions options;
  const SceneFrame frame = render_frame(options, Pose{}, 0);
  SceneKeyframes keyframes;
  for (auto _ : state) {
    keyframes.offer(frame.image, frame.truth);
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_KeyframeOffer)->Unit(benchmark::kMicrosecond);

// One frame while the object is lost (tracker_lost.cc): a rendered rim tracked for 30 frames,
// then the same background without it, so that every timed frame searches the whole frame and
// finds nothing. Arg 0: without the placements and matches of another distance or angle
// (LossOptions::view_change), 1: with them.
void BM_LostFrame(benchmark::State& state) {
  SceneOptions options;
  options.object_size = 60.0;
  const std::vector<Pose> poses =
      linear_motion_path(Pose{Point(300.0, 220.0), 0.0, 1.0}, Point(1.0, 0.5), 30);
  const cv::Mat background = render_background(options, path_region(object_model(options), poses));
  TrackerOptions tracker_options;
  tracker_options.loss.view_change.enabled = state.range(0) == 1;
  Tracker tracker(tracker_options);
  for (size_t k = 0; k < poses.size(); ++k) {
    const SceneFrame frame =
        render_frame(options, background, object_model(options), poses[k], static_cast<int>(k));
    if (k == 0) {
      tracker.init(frame.image, frame.truth);
    } else {
      tracker.track(frame.image);
    }
  }
  cv::Mat empty;
  cv::cvtColor(background, empty, cv::COLOR_GRAY2BGR);
  while (tracker.track(empty).state != TrackState::kLost) {
  }
  double ranking_ms = 0.0;
  for (auto _ : state) ranking_ms += tracker.track(empty).stages.recovery_ms;
  // The ranking of placements (and the scene registration) within the frame's time.
  state.counters["ranking_ms"] = benchmark::Counter(ranking_ms, benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_LostFrame)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace scbt

BENCHMARK_MAIN();
