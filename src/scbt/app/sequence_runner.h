// The one frame loop of every command (track, demo, eval, bench, the interactive window): frames
// from a source go through a tracker, and every result goes to the writers (results file, CSV,
// annotated video, statistics, progress). Commands differ only in the writers they plug in:
//
//   ResultsWriter results(out_path);  // frame_writers.h; or any FrameWriter of the command's own
//   RunStatistics stats;
//   SequenceRunner runner(&tracker, source.get(), {&results, optional_csv.get(), &stats}, options);
//   runner.read_first(input);
//   runner.start(initial_polygon);  // or the caller's own init, then write_initial(boundary)
//   runner.run();  // step() per frame, then commit() every writer
//
// A writer that needs more than TrackedFrame (the tracker's debug data, depth) holds a pointer to
// that source itself, as AnnotationWriter and TrackOutputs (track_outputs.h) do.
#pragma once

#include <functional>
#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

#include "scbt/io/frame_source.h"
#include "scbt/peers/polygon_tracker.h"
#include "scbt/tracker/tracker.h"

namespace scbt {

// What to do with a frame that cannot be decoded or does not fit the sequence (size change,
// unusable pixel format): hold the boundary and go on, stop with an error naming the frame, or
// let the error through unchanged.
enum class BadFramePolicy { kHold, kStop, kRaise };

// Parses "hold" / "stop". Throws std::invalid_argument naming the value.
BadFramePolicy parse_bad_frame_policy(const std::string& name);

// One frame as the writers see it.
struct TrackedFrame {
  int number = 0;                  // 1-based position in the input
  const cv::Mat* image = nullptr;  // the frame as read
  const TrackResult* result = nullptr;
  bool initial = false;  // the tracker was (re-)initialised here; result->boundary is the polygon
  std::string bad;       // non-empty: the frame could not be tracked and the boundary is held
  double wall_ms = 0.0;  // wall time of the tracker's track() call
  double cpu_ms = 0.0;   // its thread CPU time (SequenceRunOptions::measure_cpu)
};

// Where tracked frames go. Writers keep their output out of sight until commit(), so that a run
// that fails leaves nothing half-written.
class FrameWriter {
 public:
  virtual ~FrameWriter() = default;
  virtual void write(const TrackedFrame& frame) = 0;
  // Called once when the run has ended without error.
  virtual void commit() {}
};

// Frame counts and mean times over the tracked frames (paper Table I).
class RunStatistics : public FrameWriter {
 public:
  void write(const TrackedFrame& frame) override;

  int frames = 0;   // frames written, the initial one and bad ones included
  int tracked = 0;  // frames the tracker tracked
  int held = 0;     // of those, frames where it held the previous boundary
  int lost = 0;     // of those, frames in state `lost` (counted in `held` too)
  int bad = 0;      // bad frames held (BadFramePolicy::kHold)
  double line_ms = 0.0, grouping_ms = 0.0, total_ms = 0.0;  // sums over tracked frames
  double wall_ms = 0.0;                                     // sum of TrackedFrame::wall_ms
  double vertices = 0.0, edges = 0.0;                       // sums over tracked frames

  double mean(double sum) const { return tracked > 0 ? sum / tracked : 0.0; }
  // Tracked frames per second of tracking time (TrackResult::total_ms; decoding excluded).
  double fps() const { return total_ms > 0.0 ? 1000.0 * tracked / total_ms : 0.0; }
};

struct SequenceRunOptions {
  // The first frame tracked, 1-based in the input: read_first() skips the frames before it (one
  // that cannot be decoded is no error: it is not tracked). Frame numbers stay the input's.
  int start_frame = 1;
  int max_frames = 0;  // stop after this many frames from the start frame, the initial one included
  BadFramePolicy on_bad_frame = BadFramePolicy::kRaise;
  bool measure_cpu = false;  // fill TrackedFrame::cpu_ms
  // Asked before each frame; true stops the run there (a signal handler's flag, a reader gone).
  std::function<bool()> stop;
};

class SequenceRunner {
 public:
  // The writers are called in the order given (null ones skipped: optional outputs); none is
  // owned.
  SequenceRunner(PolygonTracker* tracker, FrameSource* source, std::vector<FrameWriter*> writers,
                 const SequenceRunOptions& options = {});

  // Reads the start frame; throws std::runtime_error naming `input` when there is none, or
  // std::invalid_argument when the input ends before the start frame.
  const cv::Mat& read_first(const std::string& input);
  // (Re-)initialises the tracker on the current frame and writes it as an initial frame.
  // Throws what the tracker's init throws.
  void start(const Polygon& polygon);
  // Writes the current frame as an initial frame with `boundary`, for a tracker the caller has
  // initialised on it in its own way (Tracker::init_from_box).
  void write_initial(const Polygon& boundary);
  // Reads, tracks and writes the next frame; false (nothing written) at the end of the input,
  // at max_frames or when stopped.
  bool step();
  // step() until it returns false, then commit().
  void run();
  void commit();

  int frames() const { return frames_; }  // frames read so far from the start frame on
  const cv::Mat& frame() const { return frame_; }

 private:
  void write(const TrackedFrame& frame);
  int number() const { return options_.start_frame - 1 + frames_; }  // of the current frame

  PolygonTracker* tracker_;
  FrameSource* source_;
  std::vector<FrameWriter*> writers_;
  SequenceRunOptions options_;
  cv::Mat frame_, next_;
  int frames_ = 0;
  Polygon boundary_;                          // the last boundary written, held on a bad frame
  TrackState state_ = TrackState::kTracking;  // of the last frame tracked
};

}  // namespace scbt
