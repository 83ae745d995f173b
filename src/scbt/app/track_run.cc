#include "scbt/app/track_run.h"

#include <signal.h>

#include <csignal>
#include <cstring>
#include <filesystem>
#include <memory>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>
#include <sstream>
#include <stdexcept>

#include "scbt/app/frame_writers.h"
#include "scbt/app/progress.h"
#include "scbt/geometry/polygon_io.h"
#include "scbt/io/frame_source.h"
#include "scbt/io/output_set.h"
#include "scbt/io/same_file.h"
#include "scbt/render/annotate.h"

namespace scbt {
namespace fs = std::filesystem;
namespace {

// Set by the handler; read once per frame by the tracking loop.
volatile std::sig_atomic_t g_stop_signal = 0;

extern "C" void on_stop_signal(int signal_number) { g_stop_signal = signal_number; }

// Installs on_stop_signal for SIGINT, SIGTERM and SIGHUP (a closed terminal) for its lifetime
// and ignores SIGPIPE, so that a reader of standard output going away shows as EPIPE
// (OutputSet::reader_gone) and ends the run cleanly; then restores the old handlers.
class StopSignalScope {
 public:
  explicit StopSignalScope(bool enabled) : enabled_(enabled) {
    g_stop_signal = 0;
    if (!enabled_) return;
    struct sigaction action {};
    action.sa_handler = on_stop_signal;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &old_int_);
    sigaction(SIGTERM, &action, &old_term_);
    sigaction(SIGHUP, &action, &old_hup_);
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigemptyset(&ignore.sa_mask);
    sigaction(SIGPIPE, &ignore, &old_pipe_);
  }
  ~StopSignalScope() {
    if (!enabled_) return;
    sigaction(SIGINT, &old_int_, nullptr);
    sigaction(SIGTERM, &old_term_, nullptr);
    sigaction(SIGHUP, &old_hup_, nullptr);
    sigaction(SIGPIPE, &old_pipe_, nullptr);
  }
  StopSignalScope(const StopSignalScope&) = delete;
  StopSignalScope& operator=(const StopSignalScope&) = delete;

 private:
  bool enabled_;
  struct sigaction old_int_ {};
  struct sigaction old_term_ {};
  struct sigaction old_hup_ {};
  struct sigaction old_pipe_ {};
};

const char* signal_name(int signal_number) {
  switch (signal_number) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    case SIGHUP:
      return "SIGHUP";
    default:
      return "a signal";
  }
}

void write_csv_header(std::ostream& csv) {
  csv << "frame,held,state,confidence,cost,area_similarity,detected,kept,vertices,edges,"
         "candidates,line_ms,grouping_ms,total_ms,note\n";
}

// The note is free text: quoted, with inner quotes doubled, when it holds a comma or quote.
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '\n') c = ' ';
    quoted += c;
    if (c == '"') quoted += '"';
  }
  return quoted + '"';
}

void write_csv_row(std::ostream& csv, int frame, const TrackResult& r, const std::string& note) {
  char line[256];
  std::snprintf(line, sizeof(line), "%d,%d,%s,%.4f,%.6g,%.6g,%d,%d,%d,%d,%d,%.4f,%.4f,%.4f,", frame,
                r.held ? 1 : 0, to_string(r.state).c_str(), r.confidence, r.cost, r.area_similarity,
                r.num_detected, r.num_kept, r.num_vertices, r.num_edges, r.num_candidates,
                r.line_ms, r.grouping_ms, r.total_ms());
  csv << line << csv_field(note) << '\n';
}

}  // namespace

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

cv::Rect parse_init_box(const std::string& text) {
  int values[4];
  char end = 0;
  const int read = std::sscanf(text.c_str(), "%d , %d , %d , %d %c", &values[0], &values[1],
                               &values[2], &values[3], &end);
  if (read != 4) {
    throw std::invalid_argument("--init-box must be four integers x,y,w,h (pixels), got '" + text +
                                "'");
  }
  if (values[2] <= 0 || values[3] <= 0) {
    throw std::invalid_argument("--init-box: the box " + text + " is empty (w and h must be > 0)");
  }
  return cv::Rect(values[0], values[1], values[2], values[3]);
}

namespace {

// Reads the frames before `start_frame` (1-based) and the start frame itself into `frame`. A
// skipped frame that cannot be decoded is not tracked, so it is not an error.
void read_start_frame(FrameSource* source, const TrackRunOptions& options, cv::Mat* frame) {
  const int count = source->frame_count();
  const auto beyond = [&options](int frames) {
    return std::invalid_argument("--start-frame " + std::to_string(options.start_frame) +
                                 " is beyond the input: " + options.input + " has " +
                                 std::to_string(frames) + " frame(s)");
  };
  if (count > 0 && options.start_frame > count) throw beyond(count);
  for (int skipped = 0; skipped < options.start_frame - 1; ++skipped) {
    try {
      if (!source->read(frame)) throw beyond(skipped);
    } catch (const std::runtime_error&) {
      // undecodable, but not tracked
    }
  }
  if (!source->read(frame)) {
    if (options.start_frame > 1) throw beyond(options.start_frame - 1);
    throw std::runtime_error(options.input + ": no frames");
  }
}

// Initialises the tracker on the first frame from --init / --init-points (`polygon`) or from
// --init-box; returns the initial boundary. Errors name where the boundary came from: a file's
// content (std::runtime_error, exit 1) or the command line (std::invalid_argument, exit 2).
Polygon initialise(Tracker* tracker, const cv::Mat& frame, const Polygon& polygon,
                   const TrackRunOptions& options, const std::string& frame_name) {
  const std::string where = " (first frame " + frame_name + ")";
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
    tracker->init(frame, polygon);
  } catch (const std::invalid_argument& e) {
    const std::string detail = std::string("initial polygon: ") + e.what() + where;
    if (!options.init_file.empty()) throw std::runtime_error(options.init_file + ":1: " + detail);
    throw std::invalid_argument("--init-points: " + detail);
  }
  return polygon;
}

void check_track_options(const TrackRunOptions& options) {
  if (options.output.empty()) throw std::invalid_argument("--output is required");
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

// The caption of an annotated frame: number, state, confidence, time and the chosen cycle.
std::string frame_caption(int frame_number, const TrackResult& r) {
  char status[200];
  std::snprintf(status, sizeof(status), "frame %d  %s%s  conf %.2f  %.2f ms  cost %.4f  sim %.3f",
                frame_number, to_string(r.state).c_str(), r.reacquired ? " (re-acquired)" : "",
                r.confidence, r.total_ms(), r.cost, r.area_similarity);
  return status;
}

// The outputs of a run, all opened before the first frame (a folder, a missing folder or a video
// name without a container fails here); none replaces an old file before commit().
struct TrackOutputs {
  OutputSet set;
  OutputFile* results = nullptr;
  OutputFile* csv = nullptr;
  VideoOutput* video = nullptr;
  FrameFolderOutput* frames_out = nullptr;
  std::unique_ptr<DepthTrackOutput> depth;

  TrackOutputs(const TrackRunOptions& options, double fps) {
    results = &set.add_file(options.output);
    if (!options.csv.empty()) csv = &set.add_file(options.csv);
    if (!options.video.empty()) video = &set.add_video(options.video, fps);
    if (!options.frames_out.empty()) frames_out = &set.add_frame_folder(options.frames_out);
    if (options.depth.enabled()) depth = std::make_unique<DepthTrackOutput>(options.depth, &set);
  }
  bool annotate() const { return video != nullptr || frames_out != nullptr; }
  void annotation(cv::Mat image, int frame_number) {
    if (depth) depth->draw(&image);
    if (video) video->write(image);
    if (frames_out) frames_out->write(frame_number, image);
  }
  // The initial frame: its line, 3-D row and image (no CSV row: nothing was tracked).
  void write_initial(int number, const Polygon& initial, const cv::Mat& frame) {
    TrackResult first;
    first.boundary = initial;
    first.confidence = 1.0;
    results->stream() << format_polygon_line(initial) << '\n';
    if (depth) depth->write(number, &first, frame.size());
    if (annotate()) {
      annotation(annotate_frame(frame, {}, first,
                                "frame " + std::to_string(number) + ": initial boundary"),
                 number);
    }
    set.end_record();
  }
  // A frame's line, CSV row, 3-D row and image. `debug` is null for a bad frame, which the
  // tracker did not see: no 3-D and no image then.
  void write_frame(int number, const TrackResult& r, const cv::Mat& frame, const std::string& note,
                   const TrackDebug* debug) {
    results->stream() << format_polygon_line(r.boundary) << '\n';
    if (csv) write_csv_row(csv->stream(), number, r, note);
    if (depth) depth->write(number, debug ? &r : nullptr, frame.size());
    if (annotate() && debug) {
      annotation(annotate_frame(frame, *debug, r, frame_caption(number, r)), number);
    }
    set.end_record();
  }
};

// No output may overwrite an input or another output: checked before anything is read or written.
void check_paths(const TrackRunOptions& options) {
  std::vector<NamedPath> inputs = {{"INPUT", options.input}};
  if (!options.init_file.empty()) inputs.push_back({"--init", options.init_file});
  std::vector<NamedPath> outputs = {{"-o", options.output}};
  if (!options.csv.empty()) outputs.push_back({"--csv", options.csv});
  if (!options.video.empty()) outputs.push_back({"--video", options.video});
  std::vector<NamedPath> output_folders;
  if (!options.frames_out.empty()) output_folders.push_back({"--frames-out", options.frames_out});
  add_depth_paths(options.depth, &inputs, &outputs);
  check_no_overwrite(inputs, outputs, output_folders);
}

// A bad frame under the hold policy: reported, and the boundary held. The tracker did not see
// it: no confidence, and a lost object stays lost.
TrackResult held_bad_frame(const std::string& bad, int number, const Tracker& tracker,
                           TrackState last_state, const TrackRunOptions& options,
                           std::ostream& log) {
  if (options.on_bad_frame == BadFramePolicy::kStop) {
    throw std::runtime_error(bad + " (frame " + std::to_string(number) + "; --on-bad-frame=stop)");
  }
  if (!options.quiet) log << '\n';
  log << "scbt: warning: " << printable(bad) << " (frame " << number << "); boundary held\n";
  TrackResult r;
  r.boundary = tracker.boundary();
  r.held = true;
  r.state = last_state == TrackState::kLost ? TrackState::kLost : TrackState::kUncertain;
  return r;
}

void add_to_summary(const TrackResult& r, TrackSummary* summary, double* total_ms) {
  ++summary->tracked;
  summary->held += r.held ? 1 : 0;
  summary->lost += r.state == TrackState::kLost ? 1 : 0;
  summary->mean_line_ms += r.line_ms;
  summary->mean_grouping_ms += r.grouping_ms;
  summary->mean_vertices += r.num_vertices;
  summary->mean_edges += r.num_edges;
  *total_ms += r.total_ms();
}

void finish_summary(double total_ms, TrackSummary* summary) {
  if (summary->tracked == 0) return;
  const double n = summary->tracked;
  summary->mean_line_ms /= n;
  summary->mean_grouping_ms /= n;
  summary->mean_vertices /= n;
  summary->mean_edges /= n;
  summary->fps = total_ms > 0 ? 1000.0 * n / total_ms : 0.0;
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
    log << "; " << printable(options.output) << " holds " << held_frames << "\n";
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
  check_paths(options);
  const Polygon polygon = options.init_box.empty() ? load_initial_polygon(options) : Polygon{};
  Tracker tracker(options.tracker);
  const StopSignalScope signal_scope(options.handle_signals);
  std::unique_ptr<FrameSource> source = open_colour_source(options.input, options.depth);
  TrackOutputs out(options, source->fps());

  cv::Mat frame;
  read_start_frame(source.get(), options, &frame);
  const Polygon initial = initialise(&tracker, frame, polygon, options, source->current_name());
  tracker.set_keep_debug(out.annotate());
  if (out.csv) write_csv_header(out.csv->stream());
  out.write_initial(options.start_frame, initial, frame);
  TrackSummary summary;
  summary.frames = 1;
  summary.start_frame = options.start_frame;
  if (source->frame_count() > 0) {
    summary.expected_frames = source->frame_count() - (options.start_frame - 1);
  }
  double total_ms = 0.0;
  ProgressBar progress(log, "tracking", summary.expected_frames, !options.quiet);
  TrackState last_state = TrackState::kTracking;
  while (options.max_frames <= 0 || summary.frames < options.max_frames) {
    if (g_stop_signal != 0 || out.set.reader_gone()) break;
    // A frame that cannot be decoded or does not fit (size, pixel format) is bad: reported,
    // and either held (its line repeats the boundary) or fatal, by policy.
    std::string bad;
    TrackResult r;
    try {
      if (!source->read(&frame)) break;
      r = tracker.track(frame);
    } catch (const std::runtime_error& e) {
      bad = e.what();
    } catch (const std::invalid_argument& e) {
      bad = source->current_name() + ": " + e.what();
    }
    ++summary.frames;
    const int number = options.start_frame + summary.frames - 1;  // in the input, 1-based
    if (!bad.empty()) {
      r = held_bad_frame(bad, number, tracker, last_state, options, log);
      ++summary.bad_frames;
      out.write_frame(number, r, frame, "bad frame: " + bad, nullptr);
    } else {
      last_state = r.state;
      add_to_summary(r, &summary, &total_ms);
      out.write_frame(number, r, frame, frame_note(r, frame.size()), &tracker.debug());
    }
    progress.update(summary.frames);
  }
  progress.finish(summary.frames);
  summary.stop_signal = g_stop_signal;
  if (summary.stop_signal == 0 && out.set.reader_gone()) summary.stop_signal = SIGPIPE;
  finish_summary(total_ms, &summary);
  out.set.commit();
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
