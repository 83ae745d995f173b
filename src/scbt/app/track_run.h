// The body of `scbt track`: read frames, track, write results / CSV / annotated output.
#pragma once

#include <ostream>
#include <string>

#include "scbt/tracker/tracker.h"

namespace scbt {

struct TrackRunOptions {
  std::string input;        // video file, image folder or camera index
  std::string init_file;    // polygon file; its first line is the initial boundary
  std::string init_points;  // or inline "x1,y1 x2,y2 ..."
  std::string output;       // results file: one polygon line per input frame
  std::string csv;          // optional per-frame statistics and timings
  std::string video;        // optional annotated video
  std::string frames_out;   // optional folder of annotated frames
  bool quiet = false;       // no progress bar and no summary
  int max_frames = 0;       // stop after this many frames (0: all)
  TrackerOptions tracker;
};

// One row of the paper's Table I, plus held frames.
struct TrackSummary {
  int frames = 0;  // input frames, the initial one included
  int tracked = 0;
  int held = 0;
  double mean_line_ms = 0.0;
  double mean_grouping_ms = 0.0;
  double fps = 0.0;  // tracked frames per second of tracking time (decoding excluded)
  double mean_vertices = 0.0;
  double mean_edges = 0.0;
};

// Resolves the initial polygon from init_file or init_points (exactly one must be set).
// Throws std::runtime_error / std::invalid_argument with a message naming the source.
Polygon load_initial_polygon(const TrackRunOptions& options);

// Runs the whole job. Progress and the summary go to `log` unless quiet. Throws on bad input;
// no output file is left behind by a failed run.
TrackSummary run_track(const TrackRunOptions& options, std::ostream& log);

// Formats the summary as a short human-readable block.
std::string format_summary(const TrackSummary& summary);

}  // namespace scbt
