// Line detection micro-benchmarks: our EDLines ("edlines") against OpenCV's EdgeDrawing
// ("opencv-edlines") on a synthetic 640x480 frame (a box outline over clutter and noise, as the
// tracker sees it), on the whole frame, on the tracker's window around the boundary, and on that
// window restricted to the band within 28 px of the boundary; plus the grey conversion of the
// window, and EDLines' Gaussian smoothing (ours against OpenCV's). Run pinned to one core:
//   taskset -c 0 build/bench/scbt_line_bench
#include <benchmark/benchmark.h>

#include <memory>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "scbt/lines/band_mask.h"
#include "scbt/lines/edlines.h"
#include "scbt/lines/gaussian_5x5.h"
#include "scbt/lines/line_detector.h"
#include "scbt/synthetic/scene.h"

namespace scbt {
namespace {

constexpr double kBand = 28.0;  // the tracker's filter distance 20 + ROI padding 8

const SceneFrame& scene() {
  static const SceneFrame frame = [] {
    SceneOptions options;
    options.shape = SceneShape::kBox;
    options.object_size = 120.0;
    return render_frame(options, Pose{}, 0);
  }();
  return frame;
}

const cv::Mat& gray_frame() {
  static const cv::Mat gray = [] {
    cv::Mat g;
    cv::cvtColor(scene().image, g, cv::COLOR_BGR2GRAY);
    return g;
  }();
  return gray;
}

// Arg 0: whole frame; 1: the tracker's window; 2: the window with the band.
void run(benchmark::State& state, LineDetectorKind kind) {
  const cv::Mat& gray = gray_frame();
  LineDetectorOptions options;
  options.kind = kind;
  std::unique_ptr<LineDetector> detector = make_line_detector(options);
  const int mode = static_cast<int>(state.range(0));
  const cv::Rect roi = mode == 0 ? cv::Rect(cv::Point(0, 0), gray.size())
                                 : detection_roi(scene().truth, kBand, gray.size());
  const cv::Mat window = gray(roi).clone();  // the tracker converts the window into its own Mat
  size_t count = 0;
  for (auto _ : state) {
    const std::vector<Segment> segments =
        mode == 2 ? detector->detect_near(window, roi.tl(), gray.size(), scene().truth, kBand)
                  : detector->detect_in(window, roi.tl(), gray.size());
    count = segments.size();
    benchmark::DoNotOptimize(segments.data());
  }
  state.counters["segments"] = static_cast<double>(count);
  state.counters["pixels"] = static_cast<double>(roi.area());
}

void BM_OwnEdLines(benchmark::State& state) { run(state, LineDetectorKind::kEdLines); }
void BM_OpenCvEdLines(benchmark::State& state) { run(state, LineDetectorKind::kOpenCvEdLines); }
BENCHMARK(BM_OwnEdLines)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_OpenCvEdLines)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond);

// The band mask alone (part of BM_OwnEdLines/2).
void BM_BandMask(benchmark::State& state) {
  const cv::Rect roi = detection_roi(scene().truth, kBand, gray_frame().size());
  cv::Mat mask;
  for (auto _ : state) {
    draw_band_mask(scene().truth, roi.tl(), kBand, roi.size(), &mask);
    benchmark::DoNotOptimize(mask.data);
  }
}
BENCHMARK(BM_BandMask)->Unit(benchmark::kMicrosecond);

// What fusing the grey conversion could save at most: converting the window.
void BM_WindowToGray(benchmark::State& state) {
  const cv::Rect roi = detection_roi(scene().truth, kBand, gray_frame().size());
  cv::Mat gray;
  for (auto _ : state) {
    cv::cvtColor(scene().image(roi), gray, cv::COLOR_BGR2GRAY);
    benchmark::DoNotOptimize(gray.data);
  }
}
BENCHMARK(BM_WindowToGray)->Unit(benchmark::kMicrosecond);

// EDLines' smoothing of the tracker's window: ours (gaussian_5x5.h) and OpenCV's, bit-identical.
void BM_Gaussian5x5(benchmark::State& state) {
  const cv::Mat window = gray_frame()(detection_roi(scene().truth, kBand, gray_frame().size()));
  cv::Mat smooth;
  for (auto _ : state) {
    gaussian_blur_5x5(window, &smooth);
    benchmark::DoNotOptimize(smooth.data);
  }
}
BENCHMARK(BM_Gaussian5x5)->Unit(benchmark::kMicrosecond);

void BM_OpenCvGaussian5x5(benchmark::State& state) {
  const cv::Mat window =
      gray_frame()(detection_roi(scene().truth, kBand, gray_frame().size())).clone();
  cv::Mat smooth;
  for (auto _ : state) {
    cv::GaussianBlur(window, smooth, cv::Size(5, 5), 1.0, 1.0);
    benchmark::DoNotOptimize(smooth.data);
  }
}
BENCHMARK(BM_OpenCvGaussian5x5)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace scbt

BENCHMARK_MAIN();
