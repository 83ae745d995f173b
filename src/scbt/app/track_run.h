// The body of `scbt track`: read frames, track, write results / CSV / annotated output.
#pragma once

#include <opencv2/core/types.hpp>
#include <ostream>
#include <string>

#include "scbt/app/sequence_runner.h"
#include "scbt/app/track_depth.h"
#include "scbt/tracker/tracker.h"

namespace scbt {

struct TrackRunOptions {
  std::string input;        // video file, image folder or camera index
  std::string init_file;    // polygon file; its first line is the initial boundary
  std::string init_points;  // or inline "x1,y1 x2,y2 ..."
  std::string init_box;     // or a box "x,y,w,h": the most salient closed boundary inside it
  // The first frame tracked, by its 1-based position in the input (1: the first frame read,
  // whatever number its image file carries). The results hold one line per frame from it on.
  int start_frame = 1;
  std::string output;      // results file: one polygon line per input frame
  std::string csv;         // optional per-frame statistics and timings
  std::string video;       // optional annotated video
  std::string frames_out;  // optional folder of annotated frames
  bool quiet = false;      // no progress bar and no summary
  int max_frames = 0;      // stop after this many frames (0: all)
  BadFramePolicy on_bad_frame = BadFramePolicy::kHold;
  // Catch SIGINT / SIGTERM while tracking: stop after the current frame and commit the outputs
  // for the frames tracked so far (the previous handlers are restored afterwards).
  bool handle_signals = true;
  TrackerOptions tracker;
  TrackDepthOptions depth;  // --depth ... --points3d: the boundary in 3-D (track_depth.h)
};

// One row of the paper's Table I, plus held frames.
struct TrackSummary {
  int frames = 0;       // frames from the start frame on, the initial one included
  int start_frame = 1;  // TrackRunOptions::start_frame
  int tracked = 0;
  int held = 0;
  int lost = 0;  // tracked frames in state `lost` (counted in `held` too)
  double mean_line_ms = 0.0;
  double mean_grouping_ms = 0.0;
  double fps = 0.0;  // tracked frames per second of tracking time (decoding excluded)
  double mean_vertices = 0.0;
  double mean_edges = 0.0;
  int bad_frames = 0;        // frames reported as bad and held (BadFramePolicy::kHold)
  int stop_signal = 0;       // SIGINT / SIGTERM that ended the run early, else 0
  int expected_frames = -1;  // frames the input announced, -1 if unknown
};

// Resolves the initial polygon from init_file or init_points (exactly one must be set, and no
// init_box). Throws std::runtime_error / std::invalid_argument with a message naming the source.
Polygon load_initial_polygon(const TrackRunOptions& options);

// The initial boundary of a run, and where it came from.
struct InitialPolygon {
  Polygon polygon;
  std::string source;   // "--init-points" or "FILE:LINE"
  int line = 1;         // the line of --init FILE used
  int dropped = 0;      // consecutive repeated vertices dropped
  std::string warning;  // why line 1 is used although the start frame is later
};

// The initial boundary for the start frame. From --init FILE: line N for --start-frame N when the
// file holds one polygon per frame of the input (its line count is the input's frame count, as
// for a ground-truth file), else line 1 (with a warning when N > 1 and the file has more lines).
// A vertex repeating the one before it (or the last repeating the first) is dropped: ground-truth
// files have them. Throws as load_initial_polygon.
InitialPolygon choose_initial_polygon(const TrackRunOptions& options, int input_frames);

// Parses --init-box "x,y,w,h": integers within +-1,000,000, w and h positive. Throws
// std::invalid_argument naming the value as given.
cv::Rect parse_init_box(const std::string& text);

// Runs the whole job. Progress and the summary go to `log` unless quiet; bad frames and an
// interruption are reported on `log` as one "scbt: warning: ..." line each even when quiet, as
// are vertices dropped from the initial polygon ("scbt: note: ...").
// Throws on bad input; no output file is left behind (and no existing one replaced) by a failed
// run. Interrupted by a signal, it commits complete outputs for the frames tracked so far and
// returns with stop_signal set.
TrackSummary run_track(const TrackRunOptions& options, std::ostream& log);

// Formats the summary as a short human-readable block.
std::string format_summary(const TrackSummary& summary);

}  // namespace scbt
