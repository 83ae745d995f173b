#include "scbt/app/sequence_runner.h"

#include <time.h>

#include <chrono>
#include <stdexcept>

#include "scbt/io/bounded_read.h"

namespace scbt {
namespace {

using Clock = std::chrono::steady_clock;

double thread_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

}  // namespace

BadFramePolicy parse_bad_frame_policy(const std::string& name) {
  if (name == "hold") return BadFramePolicy::kHold;
  if (name == "stop") return BadFramePolicy::kStop;
  throw std::invalid_argument("--on-bad-frame must be hold or stop, got '" + name + "'");
}

void RunStatistics::write(const TrackedFrame& frame) {
  ++frames;
  if (frame.initial) return;
  if (!frame.bad.empty()) {
    ++bad;
    return;
  }
  const TrackResult& r = *frame.result;
  ++tracked;
  held += r.held ? 1 : 0;
  lost += r.state == TrackState::kLost ? 1 : 0;
  line_ms += r.line_ms;
  grouping_ms += r.grouping_ms;
  total_ms += r.total_ms();
  wall_ms += frame.wall_ms;
  vertices += r.num_vertices;
  edges += r.num_edges;
}

SequenceRunner::SequenceRunner(PolygonTracker* tracker, FrameSource* source,
                               std::vector<FrameWriter*> writers, const SequenceRunOptions& options)
    : tracker_(tracker), source_(source), options_(options) {
  for (FrameWriter* w : writers) {
    if (w != nullptr) writers_.push_back(w);
  }
}

const cv::Mat& SequenceRunner::read_first(const std::string& input) {
  const int start = options_.start_frame;
  const int count = source_->frame_count();
  const auto beyond = [&](int frames) {
    return std::invalid_argument("--start-frame " + std::to_string(start) +
                                 " is beyond the input: " + input + " has " +
                                 std::to_string(frames) + " frame(s)");
  };
  if (count > 0 && start > count) throw beyond(count);
  for (int skipped = 0; skipped < start - 1; ++skipped) {
    try {
      if (!source_->read(&frame_)) throw beyond(skipped);
    } catch (const Interrupted&) {
      throw;
    } catch (const std::runtime_error&) {
      // undecodable, but not tracked
    }
  }
  if (!source_->read(&frame_)) {
    if (start > 1) throw beyond(start - 1);
    throw std::runtime_error(input + ": no frames");
  }
  frames_ = 1;
  return frame_;
}

void SequenceRunner::start(const Polygon& polygon) {
  tracker_->init(frame_, polygon);
  write_initial(polygon);
}

void SequenceRunner::write_initial(const Polygon& boundary) {
  TrackResult initial;
  initial.boundary = boundary;
  initial.confidence = 1.0;  // the boundary is given
  boundary_ = boundary;
  state_ = TrackState::kTracking;
  TrackedFrame f;
  f.number = number();
  f.image = &frame_;
  f.result = &initial;
  f.initial = true;
  write(f);
}

bool SequenceRunner::step() {
  if (options_.max_frames > 0 && frames_ >= options_.max_frames) return false;
  if (options_.stop && options_.stop()) return false;
  // A frame that cannot be decoded or does not fit (size, pixel format) is bad.
  TrackedFrame f;
  TrackResult r;
  try {
    // Into a second buffer, so that the end of the input leaves the last frame in place.
    if (!source_->read(&next_)) return false;
    std::swap(frame_, next_);
    const double cpu_start = options_.measure_cpu ? thread_cpu_ms() : 0.0;
    const Clock::time_point start = Clock::now();
    r = tracker_->track(frame_);
    if (options_.measure_cpu) f.cpu_ms = thread_cpu_ms() - cpu_start;
    f.wall_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  } catch (const Interrupted&) {
    return false;  // a stop signal came while the frame was read: the run ends before it
  } catch (const std::runtime_error& e) {
    if (options_.on_bad_frame == BadFramePolicy::kRaise) throw;
    f.bad = e.what();
  } catch (const std::invalid_argument& e) {
    if (options_.on_bad_frame == BadFramePolicy::kRaise) throw;
    f.bad = source_->current_name() + ": " + e.what();
  }
  ++frames_;
  if (!f.bad.empty()) {
    if (options_.on_bad_frame == BadFramePolicy::kStop) {
      throw std::runtime_error(f.bad + " (frame " + std::to_string(number()) +
                               "; --on-bad-frame=stop)");
    }
    // The tracker did not see the frame: no confidence, and a lost object stays lost.
    r = TrackResult();
    r.boundary = boundary_;
    r.held = true;
    r.state = state_ == TrackState::kLost ? TrackState::kLost : TrackState::kUncertain;
  } else {
    state_ = r.state;
  }
  f.number = number();
  f.image = &frame_;
  f.result = &r;
  write(f);
  boundary_ = std::move(r.boundary);
  return true;
}

void SequenceRunner::run() {
  while (step()) {
  }
  commit();
}

void SequenceRunner::commit() {
  for (FrameWriter* w : writers_) w->commit();
}

void SequenceRunner::write(const TrackedFrame& frame) {
  for (FrameWriter* w : writers_) w->write(frame);
}

}  // namespace scbt
