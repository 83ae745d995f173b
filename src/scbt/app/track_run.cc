#include "scbt/app/track_run.h"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <memory>
#include <stdexcept>

#include "scbt/app/frame_writers.h"
#include "scbt/app/stop_signal.h"
#include "scbt/app/track_outputs.h"
#include "scbt/geometry/polygon_io.h"
#include "scbt/io/bounded_read.h"
#include "scbt/io/frame_source.h"
#include "scbt/io/printable.h"
#include "scbt/io/same_file.h"
#include "scbt/peers/polygon_tracker.h"

namespace scbt {

Polygon load_initial_polygon(const TrackRunOptions& options) {
  const int given = (options.init_file.empty() ? 0 : 1) + (options.init_points.empty() ? 0 : 1) +
                    (options.init_box.empty() ? 0 : 1);
  if (given != 1 || !options.init_box.empty()) {
    throw std::invalid_argument(
        "give exactly one of --init FILE, --init-points \"x,y ...\" or --init-box x,y,w,h");
  }
  if (!options.init_file.empty()) return read_first_polygon(options.init_file);
  try {
    return parse_points_list(options.init_points);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("--init-points: ") + e.what());
  }
}

InitialPolygon choose_initial_polygon(const TrackRunOptions& options, int input_frames) {
  InitialPolygon chosen;
  if (options.init_file.empty()) {
    chosen.polygon = load_initial_polygon(options);
    chosen.source = "--init-points";
  } else {
    std::vector<std::string> lines = read_polygon_lines(options.init_file);
    // Trailing blank lines (an editor's final newline) are not polygons.
    while (lines.size() > 1 && lines.back().find_first_not_of(" \t") == std::string::npos) {
      lines.pop_back();
    }
    const int count = static_cast<int>(lines.size());
    const int start = options.start_frame;
    if (count > 1 && count == input_frames && start <= count) {
      chosen.line = start;  // one polygon per frame, as a ground-truth file: frame N's own
    } else if (count > 1 && start > 1) {
      chosen.warning = printable(options.init_file) + " has " + std::to_string(count) +
                       " lines, not one per frame of " + printable(options.input) + " (" +
                       (input_frames > 0 ? std::to_string(input_frames) : "unknown") +
                       " frames): its first line is the boundary on frame " + std::to_string(start);
    }
    chosen.source = printable(options.init_file) + ":" + std::to_string(chosen.line);
    std::string error;
    if (!try_parse_polygon_line(lines[chosen.line - 1], &chosen.polygon, &error)) {
      throw std::runtime_error(chosen.source + ": " + error);
    }
  }
  chosen.dropped = drop_repeated_vertices(&chosen.polygon);
  return chosen;
}

cv::Rect parse_init_box(const std::string& text) {
  const auto malformed = [&] {
    return std::invalid_argument("--init-box must be four integers x,y,w,h (pixels), got '" +
                                 printable(text) + "'");
  };
  // Each value as given, whole, in the range of a pixel coordinate: never wrapped or cut.
  long long values[4];
  std::size_t at = 0;
  for (int i = 0; i < 4; ++i) {
    const std::size_t comma = i < 3 ? text.find(',', at) : text.size();
    if (comma == std::string::npos) throw malformed();
    std::string token = text.substr(at, comma - at);
    token.erase(0, token.find_first_not_of(" \t"));
    token.erase(token.find_last_not_of(" \t") + 1);
    at = comma + 1;
    if (token.empty()) throw malformed();
    errno = 0;
    char* end = nullptr;
    values[i] = std::strtoll(token.c_str(), &end, 10);
    if (end != token.c_str() + token.size()) throw malformed();
    constexpr long long kLimit = 1000000;  // beyond any frame scbt can track
    if (errno == ERANGE || values[i] < -kLimit || values[i] > kLimit) {
      throw std::invalid_argument("--init-box: " + std::string("xywh").substr(i, 1) + " = " +
                                  printable(token) + " is out of range (at most " +
                                  std::to_string(kLimit) + " in magnitude)");
    }
  }
  if (values[2] <= 0 || values[3] <= 0) {
    throw std::invalid_argument("--init-box: the box " + printable(text) +
                                " is empty (w and h must be > 0)");
  }
  return cv::Rect(static_cast<int>(values[0]), static_cast<int>(values[1]),
                  static_cast<int>(values[2]), static_cast<int>(values[3]));
}

namespace {

// Initialises the tracker on the first frame from --init / --init-points (`polygon`) or from
// --init-box; returns the initial boundary. Errors name where the boundary came from: a file's
// content (std::runtime_error, exit 1) or the command line (std::invalid_argument, exit 2).
Polygon initialise(Tracker* tracker, const cv::Mat& frame, const InitialPolygon& polygon,
                   const TrackRunOptions& options, const std::string& frame_name) {
  const std::string where = " (first frame " + printable(frame_name) + ")";
  if (!options.init_box.empty()) {
    const cv::Rect box = parse_init_box(options.init_box);
    try {
      return tracker->init_from_box(frame, box);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("--init-box: " + std::string(e.what()) + where);
    } catch (const std::runtime_error& e) {
      throw std::runtime_error("--init-box " + options.init_box + ": " + e.what() + where);
    }
  }
  try {
    tracker->init(frame, polygon.polygon);
  } catch (const std::invalid_argument& e) {
    const std::string detail = std::string("initial polygon: ") + e.what() + where;
    if (!options.init_file.empty()) throw std::runtime_error(polygon.source + ": " + detail);
    throw std::invalid_argument("--init-points: " + detail);
  }
  return polygon.polygon;
}

void check_track_options(const TrackRunOptions& options) {
  if (options.output.empty() && options.csv.empty() && options.video.empty() &&
      options.frames_out.empty() && !options.depth.enabled()) {
    throw std::invalid_argument(
        "nothing to write: give -o/--output, --csv, --video, --frames-out or --points3d");
  }
  if (options.max_frames < 0) {
    throw std::invalid_argument("--max-frames must be >= 0, got " +
                                std::to_string(options.max_frames));
  }
  if (options.start_frame < 1) {
    throw std::invalid_argument("--start-frame is 1-based (1: the first frame), got " +
                                std::to_string(options.start_frame));
  }
  if (!options.init_box.empty()) {
    if (!options.init_file.empty() || !options.init_points.empty()) {
      throw std::invalid_argument("--init-box cannot be combined with --init or --init-points");
    }
    parse_init_box(options.init_box);  // a malformed box fails before any work
  }
  options.depth.check();
}

// A bad frame held (BadFramePolicy::kHold) is reported at once, even when quiet.
class BadFrameWarnings : public FrameWriter {
 public:
  BadFrameWarnings(std::ostream& log, ProgressWriter* progress) : log_(log), progress_(progress) {}
  void write(const TrackedFrame& frame) override {
    if (frame.bad.empty()) return;
    progress_->break_line();
    log_ << "scbt: warning: " << printable(frame.bad) << " (frame " << frame.number
         << "); boundary held\n";
  }

 private:
  std::ostream& log_;
  ProgressWriter* progress_;
};

TrackSummary summarise(const RunStatistics& stats, int start_frame, int expected_frames) {
  TrackSummary summary;
  summary.frames = stats.frames;
  summary.start_frame = start_frame;
  summary.expected_frames = expected_frames;
  summary.tracked = stats.tracked;
  summary.held = stats.held;
  summary.lost = stats.lost;
  summary.bad_frames = stats.bad;
  summary.mean_line_ms = stats.mean(stats.line_ms);
  summary.mean_grouping_ms = stats.mean(stats.grouping_ms);
  summary.fps = stats.fps();
  summary.mean_vertices = stats.mean(stats.vertices);
  summary.mean_edges = stats.mean(stats.edges);
  return summary;
}

// The warnings at the end of a run: interrupted, bad frames, frames the input announced but did
// not give (those count as bad frames: exit code 3).
void report_end(const TrackRunOptions& options, std::ostream& log, TrackSummary* summary) {
  const int last = summary->start_frame + summary->frames - 1;
  const std::string held_frames =
      "frames " + std::to_string(summary->start_frame) + ".." + std::to_string(last);
  if (summary->stop_signal == SIGPIPE) {
    log << "scbt: warning: the reader of a streamed output went away (EPIPE) after frame " << last
        << "; the other outputs hold " << held_frames << "\n";
  } else if (summary->stop_signal != 0) {
    log << "scbt: warning: interrupted by " << signal_name(summary->stop_signal) << " after frame "
        << last;
    if (summary->expected_frames > 0) {
      log << " of " << summary->start_frame + summary->expected_frames - 1;
    }
    const std::string& first_output = !options.output.empty()   ? options.output
                                      : !options.csv.empty()    ? options.csv
                                      : options.depth.enabled() ? options.depth.points3d
                                      : !options.video.empty()  ? options.video
                                                                : options.frames_out;
    log << "; " << printable(first_output) << " holds " << held_frames << "\n";
  }
  if (summary->bad_frames > 0) {
    log << "scbt: warning: " << summary->bad_frames << " bad frame(s) reported and held\n";
  }
  const bool cut_short = options.max_frames > 0 && summary->frames >= options.max_frames;
  if (summary->stop_signal == 0 && !cut_short && summary->expected_frames > 0 &&
      summary->frames < summary->expected_frames) {
    // Frames lost without a trace (no timestamp gap) cannot be placed: later lines may be early.
    log << "scbt: warning: " << printable(options.input) << " gave " << last << " of the "
        << summary->start_frame + summary->expected_frames - 1
        << " frames it announced (it ended early, or frames were lost in decoding)\n";
    summary->bad_frames += summary->expected_frames - summary->frames;
  }
}

}  // namespace

TrackSummary run_track(const TrackRunOptions& options, std::ostream& log) {
  check_track_options(options);
  check_track_paths(options);
  // Read (bounded) before the input is opened, parsed once its frame count is known.
  if (!options.init_file.empty()) read_polygon_lines(options.init_file);
  if (!options.init_points.empty()) load_initial_polygon(options);
  BdspPolygonTracker bdsp{Tracker(options.tracker)};
  const StopSignalScope signals(options.handle_signals);
  std::unique_ptr<FrameSource> source = open_colour_source(options.input, options.depth);
  InitialPolygon polygon;
  if (options.init_box.empty()) {
    polygon = choose_initial_polygon(options, source->frame_count());
    if (!polygon.warning.empty()) log << "scbt: warning: " << polygon.warning << "\n";
    if (polygon.dropped > 0) {
      log << "scbt: note: " << polygon.source << ": " << polygon.dropped
          << " repeated vertex(es) dropped from the initial polygon\n";
    }
  }
  TrackOutputs out(options, source->fps(), &bdsp.tracker());
  const int expected =
      source->frame_count() > 0 ? source->frame_count() - (options.start_frame - 1) : -1;

  // The frames that will run: to the end of the input, or --max-frames of them.
  int will_run = expected;
  if (options.max_frames > 0 && (will_run <= 0 || will_run > options.max_frames)) {
    will_run = options.max_frames;
  }
  ProgressWriter progress(log, "tracking", will_run, !options.quiet);
  BadFrameWarnings warnings(log, &progress);
  RunStatistics stats;
  SequenceRunOptions run_options;
  run_options.start_frame = options.start_frame;
  run_options.max_frames = options.max_frames;
  run_options.on_bad_frame = options.on_bad_frame;
  run_options.stop = [&] { return signals.stop_signal() != 0 || out.reader_gone(); };
  SequenceRunner runner(&bdsp, source.get(), {&warnings, &out, &stats, &progress}, run_options);
  const cv::Mat& frame = runner.read_first(options.input);
  runner.write_initial(
      initialise(&bdsp.tracker(), frame, polygon, options, source->current_name()));
  bdsp.tracker().set_keep_debug(out.annotate());
  while (runner.step()) {
  }
  progress.finish();

  TrackSummary summary = summarise(stats, options.start_frame, expected);
  summary.stop_signal = signals.stop_signal();
  if (summary.stop_signal == 0 && out.reader_gone()) summary.stop_signal = SIGPIPE;
  runner.commit();
  report_end(options, log, &summary);
  if (!options.quiet) log << format_summary(summary);
  return summary;
}

std::string format_summary(const TrackSummary& s) {
  char text[512];
  std::snprintf(text, sizeof(text),
                "frames %d (tracked %d, held %d, lost %d)\n"
                "mean line time %.3f ms, grouping time %.3f ms, %.1f fps\n"
                "mean graph vertices %.1f, edges %.1f\n",
                s.frames, s.tracked, s.held, s.lost, s.mean_line_ms, s.mean_grouping_ms, s.fps,
                s.mean_vertices, s.mean_edges);
  return text;
}

}  // namespace scbt
