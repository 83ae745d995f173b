// Cost of the lift to 3-D (issue 20 target: <= 0.1 ms per frame for a 100-vertex boundary): a
// bowl's and a box's rim rendered at 0.6 and 1.5 m with the sensor model (20 % of the outline's
// depth lost), the boundary resampled to 100 vertices.
#include <benchmark/benchmark.h>

#include <cmath>

#include "scbt/depth/boundary_3d.h"
#include "scbt/synthetic/rgbd_scene.h"
#include "scbt/synthetic/rgbd_sensor.h"

namespace scbt {
namespace {

struct Input {
  Polygon boundary;
  cv::Mat depth;
  PinholeIntrinsics camera;
};

Input make_input(RimShape shape, double distance) {
  RgbdSceneOptions scene;
  scene.shape = shape;
  scene.rim_vertices = 100;
  scene.box_edge_pieces = 25;  // 100 vertices for the box too
  RimPose pose;
  pose.centre = {0.02, -0.01, distance};
  const RgbdFrame frame = render_rgbd_frame(scene, pose);
  return {frame.truth, apply_depth_sensor(frame.clean_depth, frame.truth, DepthSensorOptions{}),
          scene.camera};
}

void BM_LiftBoundaryTo3d(benchmark::State& state) {
  const RimShape shape = state.range(0) == 0 ? RimShape::kBowl : RimShape::kBox;
  const double distance = state.range(1) / 10.0;
  const Input input = make_input(shape, distance);
  int samples = 0;
  for (auto _ : state) {
    const Boundary3d rim = lift_boundary_to_3d(input.boundary, input.depth, input.camera);
    samples = rim.n_samples;
    benchmark::DoNotOptimize(rim.centroid);
  }
  state.counters["vertices"] = static_cast<double>(input.boundary.size());
  state.counters["samples"] = samples;
  state.SetLabel(std::string(shape == RimShape::kBowl ? "bowl" : "box") + " at " +
                 std::to_string(distance).substr(0, 3) + " m");
}
BENCHMARK(BM_LiftBoundaryTo3d)
    ->Args({0, 6})
    ->Args({0, 15})
    ->Args({1, 6})
    ->Args({1, 15})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace scbt

BENCHMARK_MAIN();
