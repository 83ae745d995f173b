// The body of `scbt bench`: time the tracker stage by stage on the dataset, in the optimised
// configuration and in the straightforward one (whole-frame line detection, BDSP on a generic
// graph: Boost.Graph's Dijkstra with every candidate materialised), in the same run, one pass
// over each sequence per configuration, and score both against the ground truth after each pass
// (scoring between frames would evict the tracker's data from the cache).
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "scbt/tracker/tracker_options.h"

namespace scbt {

struct BenchRunOptions {
  std::string dataset;                 // the dataset root (see list_dataset_sequences)
  std::vector<std::string> sequences;  // empty: all
  int max_frames = 0;                  // per sequence, the initial one included (0: all)
  TrackerOptions tracker;              // the configuration under test
  bool compare = true;                 // also run the straightforward configuration
  std::string csv;                     // optional: per-sequence, per-configuration rows
  bool quiet = false;                  // no progress on the log

  // Throws std::invalid_argument naming the first bad value.
  void check() const;
};

// Order statistics of per-frame times (milliseconds).
struct TimeStats {
  double mean = 0.0;
  double median = 0.0;
  double p90 = 0.0;
  double p99 = 0.0;
  double max = 0.0;
};

// Nearest-rank statistics of `samples` (all zero when empty).
TimeStats time_stats(std::vector<double> samples);

struct BenchConfigResult {
  std::string config;  // "optimised" or "straightforward"
  TimeStats line;      // colour conversion + line detection
  TimeStats grouping;  // filter + graph + BDSP + choice
  // The grouping stages one by one (a lost frame's motion estimate is only in `grouping`).
  TimeStats filter, graph, search, choice;
  TimeStats total;   // the whole Tracker::track call (wall clock)
  TimeStats cpu;     // the same call in CPU time of the thread: robust to a shared machine
  double fps = 0.0;  // tracked frames per second of tracking time
  int held = 0;
  double success_10px = 0.0;  // share of frames (the initial one included) with E_AL < 10
  double mean_detected = 0.0;
};

struct BenchSequenceResult {
  std::string name;
  int frames = 0;                          // the initial one included
  std::vector<BenchConfigResult> configs;  // optimised first
  long peak_rss_kb = 0;                    // process peak after this sequence (getrusage)
  double speedup = 0.0;  // mean total time straightforward / optimised (0 without comparison)
};

struct BenchReport {
  std::vector<BenchSequenceResult> sequences;
  double mean_total_ms = 0.0;     // optimised: mean over sequences of the per-frame mean
  double slowest_total_ms = 0.0;  // optimised: the largest per-sequence mean
  double baseline_mean_total_ms = 0.0;
  double mean_cpu_ms = 0.0;  // the same three in thread CPU time
  double slowest_cpu_ms = 0.0;
  double baseline_mean_cpu_ms = 0.0;
};

// Runs the benchmark. Decoding is done once per frame and excluded from the times; each frame
// is tracked by both configurations in turn so that machine noise hits them alike.
BenchReport run_bench(const BenchRunOptions& options, std::ostream& log);

// Markdown tables: per sequence and configuration, and a Table I style summary.
std::string format_bench_report(const BenchReport& report);

}  // namespace scbt
