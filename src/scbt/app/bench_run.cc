#include "scbt/app/bench_run.h"

#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "scbt/app/frame_writers.h"
#include "scbt/app/sequence_runner.h"
#include "scbt/eval/alignment_error.h"
#include "scbt/eval/dataset.h"
#include "scbt/geometry/polygon_io.h"
#include "scbt/io/atomic_file.h"
#include "scbt/io/frame_source.h"
#include "scbt/reference/generic_cycle_stage.h"
#include "scbt/tracker/tracker.h"
#include "scbt/tracker/tracker_with_stage.h"

namespace scbt {
namespace {

long peak_rss_kb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;  // kilobytes on Linux
}

std::vector<Polygon> read_truth(const std::string& path) {
  std::vector<Polygon> truth;
  for (const std::string& line : read_text_lines(path)) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    truth.push_back(parse_polygon_line(line));
  }
  if (truth.empty()) throw std::runtime_error(path + ": no ground truth");
  return truth;
}

// Per-frame samples of one configuration.
struct Samples : FrameWriter {
  std::string config;
  std::unique_ptr<BdspPolygonTracker> tracker;
  std::vector<double> line, grouping, total, cpu;
  std::vector<double> filter, graph, search, choice;
  std::vector<Polygon> boundaries;  // per frame, the initial one first
  std::vector<double> errors;
  int held = 0;
  double detected = 0.0;

  void write(const TrackedFrame& f) override {
    const TrackResult& r = *f.result;
    boundaries.push_back(r.boundary);
    if (f.initial) return;
    cpu.push_back(f.cpu_ms);
    total.push_back(f.wall_ms);
    line.push_back(r.line_ms);
    grouping.push_back(r.grouping_ms);
    filter.push_back(r.stages.filter_ms);
    graph.push_back(r.stages.graph_ms);
    search.push_back(r.stages.search_ms);
    choice.push_back(r.stages.choice_ms);
    held += r.held ? 1 : 0;
    detected += r.num_detected;
  }
};

Samples make_samples(const std::string& config, Tracker tracker) {
  Samples samples;
  samples.config = config;
  samples.tracker = std::make_unique<BdspPolygonTracker>(std::move(tracker));
  return samples;
}

// Tracks the sequence with one configuration into `run` (its samples and boundaries) and scores
// the boundaries afterwards. Returns the frame count.
int track_pass(const DatasetSequence& sequence, const std::vector<Polygon>& truth,
               const BenchRunOptions& options, int total_frames, FrameSource* source, Samples* run,
               std::ostream& log) {
  ProgressWriter progress(log, sequence.name + " " + run->config, total_frames, !options.quiet, 25);
  SequenceRunOptions run_options;
  run_options.max_frames = options.max_frames;
  run_options.measure_cpu = true;
  SequenceRunner runner(run->tracker.get(), source, {run, &progress}, run_options);
  const cv::Size canvas = runner.read_first(sequence.frames).size();
  runner.start(truth.front());
  runner.run();
  progress.finish();
  for (size_t k = 0; k < run->boundaries.size(); ++k) {
    run->errors.push_back(k < truth.size() ? alignment_error(run->boundaries[k], truth[k], canvas)
                                           : std::numeric_limits<double>::infinity());
  }
  return runner.frames();
}

BenchConfigResult summarise(const Samples& s) {
  BenchConfigResult r;
  r.config = s.config;
  r.line = time_stats(s.line);
  r.grouping = time_stats(s.grouping);
  r.filter = time_stats(s.filter);
  r.graph = time_stats(s.graph);
  r.search = time_stats(s.search);
  r.choice = time_stats(s.choice);
  r.total = time_stats(s.total);
  r.cpu = time_stats(s.cpu);
  r.fps = r.total.mean > 0.0 ? 1000.0 / r.total.mean : 0.0;
  r.held = s.held;
  r.success_10px = success_rate(s.errors, 10.0);
  r.mean_detected = s.total.empty() ? 0.0 : s.detected / static_cast<double>(s.total.size());
  return r;
}

std::string fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", decimals, value);
  return text;
}

}  // namespace

void BenchRunOptions::check() const {
  if (dataset.empty()) throw std::invalid_argument("dataset folder is required");
  if (max_frames < 0) {
    throw std::invalid_argument("max_frames must be >= 0, got " + std::to_string(max_frames));
  }
  tracker.check();
}

TimeStats time_stats(std::vector<double> samples) {
  TimeStats stats;
  if (samples.empty()) return stats;
  std::sort(samples.begin(), samples.end());
  const size_t n = samples.size();
  auto rank = [&](double q) {
    const size_t k = static_cast<size_t>(std::ceil(q * static_cast<double>(n)));
    return samples[std::clamp<size_t>(k, 1, n) - 1];
  };
  double sum = 0.0;
  for (double x : samples) sum += x;
  stats.mean = sum / static_cast<double>(n);
  stats.median = rank(0.5);
  stats.p90 = rank(0.9);
  stats.p99 = rank(0.99);
  stats.max = samples.back();
  return stats;
}

namespace {

void write_csv_header(std::ostream& csv) {
  csv << "sequence,config,frames,line_median_ms,line_p90_ms,line_p99_ms,"
         "grouping_median_ms,grouping_p90_ms,grouping_p99_ms,filter_median_ms,"
         "graph_median_ms,search_median_ms,choice_median_ms,filter_mean_ms,"
         "graph_mean_ms,search_mean_ms,choice_mean_ms,total_mean_ms,"
         "total_median_ms,total_p90_ms,total_p99_ms,cpu_mean_ms,cpu_median_ms,fps,held,"
         "success_10px,"
         "mean_detected,peak_rss_kb\n";
}

void write_csv_rows(std::ostream& csv, const BenchSequenceResult& result) {
  for (const BenchConfigResult& c : result.configs) {
    csv << result.name << ',' << c.config << ',' << result.frames << ',' << c.line.median << ','
        << c.line.p90 << ',' << c.line.p99 << ',' << c.grouping.median << ',' << c.grouping.p90
        << ',' << c.grouping.p99 << ',' << c.filter.median << ',' << c.graph.median << ','
        << c.search.median << ',' << c.choice.median << ',' << c.filter.mean << ',' << c.graph.mean
        << ',' << c.search.mean << ',' << c.choice.mean << ',' << c.total.mean << ','
        << c.total.median << ',' << c.total.p90 << ',' << c.total.p99 << ',' << c.cpu.mean << ','
        << c.cpu.median << ',' << c.fps << ',' << c.held << ',' << c.success_10px << ','
        << c.mean_detected << ',' << result.peak_rss_kb << '\n';
  }
}

// Both configurations over one sequence, each in a pass of its own.
BenchSequenceResult bench_sequence(const DatasetSequence& sequence, const BenchRunOptions& options,
                                   std::ostream& log) {
  const std::vector<Polygon> truth = read_truth(sequence.ground_truth);
  std::unique_ptr<FrameSource> source = open_frame_source(sequence.frames);
  int total_frames = source->frame_count();
  if (options.max_frames > 0 && (total_frames < 0 || total_frames > options.max_frames)) {
    total_frames = options.max_frames;
  }

  std::vector<Samples> runs;
  runs.push_back(make_samples("optimised", Tracker(options.tracker)));
  if (options.compare) {
    TrackerOptions plain = options.tracker;
    plain.detector.crop_to_boundary = false;
    // The straightforward detector is OpenCV's EdgeDrawing, the library implementation of the
    // paper's EDLines; other detectors are compared with themselves on the whole frame.
    if (plain.detector.kind == LineDetectorKind::kEdLines) {
      plain.detector.kind = LineDetectorKind::kOpenCvEdLines;
    }
    // Stages 5-6 from reference/: BDSP on Boost.Graph, every candidate materialised.
    runs.push_back(make_samples("straightforward", make_tracker(plain, [] {
                                  return std::make_unique<GenericCycleStage>();
                                })));
  }

  // Each configuration tracks the sequence in a pass of its own, as it would run alone, and
  // the frames are scored after the pass: scoring a frame (a distance transform of the whole
  // frame) between two tracked frames would evict the tracker's working set from the cache,
  // which a tracker alone never sees. Decoding the frames stays between them, as in use.
  int frames = 0;
  for (Samples& run : runs) {
    std::unique_ptr<FrameSource> pass_source =
        &run == &runs.front() ? std::move(source) : open_frame_source(sequence.frames);
    frames = track_pass(sequence, truth, options, total_frames, pass_source.get(), &run, log);
  }

  BenchSequenceResult result;
  result.name = sequence.name;
  result.frames = frames;
  for (const Samples& run : runs) result.configs.push_back(summarise(run));
  result.peak_rss_kb = peak_rss_kb();
  if (result.configs.size() > 1 && result.configs[0].total.mean > 0.0) {
    result.speedup = result.configs[1].total.mean / result.configs[0].total.mean;
  }
  return result;
}

// The means over sequences.
void summarise_report(BenchReport* report_pointer) {
  BenchReport& report = *report_pointer;
  for (const BenchSequenceResult& s : report.sequences) {
    report.mean_total_ms += s.configs[0].total.mean;
    report.slowest_total_ms = std::max(report.slowest_total_ms, s.configs[0].total.mean);
    report.mean_cpu_ms += s.configs[0].cpu.mean;
    report.slowest_cpu_ms = std::max(report.slowest_cpu_ms, s.configs[0].cpu.mean);
    if (s.configs.size() > 1) {
      report.baseline_mean_total_ms += s.configs[1].total.mean;
      report.baseline_mean_cpu_ms += s.configs[1].cpu.mean;
    }
  }
  if (!report.sequences.empty()) {
    report.mean_total_ms /= static_cast<double>(report.sequences.size());
    report.baseline_mean_total_ms /= static_cast<double>(report.sequences.size());
    report.mean_cpu_ms /= static_cast<double>(report.sequences.size());
    report.baseline_mean_cpu_ms /= static_cast<double>(report.sequences.size());
  }
}

}  // namespace

BenchReport run_bench(const BenchRunOptions& options, std::ostream& log) {
  options.check();
  const std::vector<DatasetSequence> sequences =
      select_dataset_sequences(options.dataset, options.sequences);
  std::unique_ptr<AtomicFile> csv;
  if (!options.csv.empty()) {
    csv = std::make_unique<AtomicFile>(options.csv);
    write_csv_header(csv->stream());
  }
  BenchReport report;
  for (const DatasetSequence& sequence : sequences) {
    report.sequences.push_back(bench_sequence(sequence, options, log));
    if (csv) write_csv_rows(csv->stream(), report.sequences.back());
  }
  summarise_report(&report);
  if (csv) csv->commit();
  return report;
}

std::string format_bench_report(const BenchReport& report) {
  std::ostringstream out;
  out << "| sequence | config | frames | line ms median/p90/p99 | grouping ms median/p90/p99 | "
         "total ms mean/median/p90/p99 | CPU ms mean/median | fps | held | success@10px | peak RSS "
         "MB | "
         "speed-up |\n"
         "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const BenchSequenceResult& s : report.sequences) {
    for (size_t k = 0; k < s.configs.size(); ++k) {
      const BenchConfigResult& c = s.configs[k];
      out << "| " << s.name << " | " << c.config << " | " << s.frames << " | "
          << fixed(c.line.median, 3) << " / " << fixed(c.line.p90, 3) << " / "
          << fixed(c.line.p99, 3) << " | " << fixed(c.grouping.median, 3) << " / "
          << fixed(c.grouping.p90, 3) << " / " << fixed(c.grouping.p99, 3) << " | "
          << fixed(c.total.mean, 3) << " / " << fixed(c.total.median, 3) << " / "
          << fixed(c.total.p90, 3) << " / " << fixed(c.total.p99, 3) << " | "
          << fixed(c.cpu.mean, 3) << " / " << fixed(c.cpu.median, 3) << " | " << fixed(c.fps, 0)
          << " | " << c.held << " | " << fixed(c.success_10px, 3) << " | "
          << fixed(s.peak_rss_kb / 1024.0, 1) << " | "
          << (k == 0 && s.speedup > 0.0 ? fixed(s.speedup, 2) + "x" : std::string("")) << " |\n";
    }
  }
  out << "\nGrouping stage by stage, ms mean / p99 (optimised configuration):\n\n"
         "| sequence | filter | graph | BDSP | choice |\n|---|---|---|---|---|\n";
  for (const BenchSequenceResult& s : report.sequences) {
    const BenchConfigResult& c = s.configs[0];
    auto cell = [](const TimeStats& t) { return fixed(t.mean, 3) + " / " + fixed(t.p99, 3); };
    out << "| " << s.name << " | " << cell(c.filter) << " | " << cell(c.graph) << " | "
        << cell(c.search) << " | " << cell(c.choice) << " |\n";
  }
  out << "\nTable I style (optimised configuration, one core):\n\n"
         "| sequence | line detection ms | grouping ms | fps |\n|---|---|---|---|\n";
  for (const BenchSequenceResult& s : report.sequences) {
    const BenchConfigResult& c = s.configs[0];
    out << "| " << s.name << " | " << fixed(c.line.mean, 3) << " | " << fixed(c.grouping.mean, 3)
        << " | " << fixed(c.fps, 0) << " |\n";
  }
  out << "\nmean tracking time per frame over sequences: " << fixed(report.mean_total_ms, 3)
      << " ms; slowest sequence: " << fixed(report.slowest_total_ms, 3) << " ms";
  if (report.baseline_mean_total_ms > 0.0) {
    out << "; straightforward: " << fixed(report.baseline_mean_total_ms, 3) << " ms ("
        << fixed(report.baseline_mean_total_ms / std::max(1e-9, report.mean_total_ms), 2) << "x)";
  }
  out << "\nin thread CPU time: " << fixed(report.mean_cpu_ms, 3)
      << " ms; slowest sequence: " << fixed(report.slowest_cpu_ms, 3) << " ms";
  if (report.baseline_mean_cpu_ms > 0.0) {
    out << "; straightforward: " << fixed(report.baseline_mean_cpu_ms, 3) << " ms ("
        << fixed(report.baseline_mean_cpu_ms / std::max(1e-9, report.mean_cpu_ms), 2) << "x)";
  }
  out << '\n';
  return out.str();
}

}  // namespace scbt
