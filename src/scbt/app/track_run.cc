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
  csv << "frame,held,cost,area_similarity,detected,kept,vertices,edges,candidates,line_ms,"
         "grouping_ms,total_ms,note\n";
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
  std::snprintf(line, sizeof(line), "%d,%d,%.6g,%.6g,%d,%d,%d,%d,%d,%.4f,%.4f,%.4f,", frame,
                r.held ? 1 : 0, r.cost, r.area_similarity, r.num_detected, r.num_kept,
                r.num_vertices, r.num_edges, r.num_candidates, r.line_ms, r.grouping_ms,
                r.total_ms());
  csv << line << csv_field(note) << '\n';
}

// Why a frame was hard, in words, for the CSV's note column ("" for an ordinary frame).
std::string frame_note(const TrackResult& r, const cv::Size& size) {
  std::string note;
  auto add = [&note](const std::string& text) { note += (note.empty() ? "" : "; ") + text; };
  if (r.num_dropped > 0) {
    add("segments capped: " + std::to_string(r.num_dropped) + " of " +
        std::to_string(r.num_kept + r.num_dropped) + " near the boundary dropped");
  }
  if (r.held) {
    if (r.num_detected == 0) {
      add("held: no segments detected");
    } else if (r.num_kept == 0) {
      add("held: no segments near the boundary");
    } else if (r.num_candidates == 0) {
      add("held: no closed cycle among the segments");
    } else {
      add("held: every candidate rejected");
    }
  }
  int outside = 0;
  for (const Point& p : r.boundary) {
    outside += (p.x < 0 || p.y < 0 || p.x > size.width || p.y > size.height) ? 1 : 0;
  }
  if (outside > 0) add(std::to_string(outside) + " boundary vertices outside the frame");
  return note;
}

}  // namespace

BadFramePolicy parse_bad_frame_policy(const std::string& name) {
  if (name == "hold") return BadFramePolicy::kHold;
  if (name == "stop") return BadFramePolicy::kStop;
  throw std::invalid_argument("--on-bad-frame must be hold or stop, got '" + name + "'");
}

Polygon load_initial_polygon(const TrackRunOptions& options) {
  if (options.init_file.empty() == options.init_points.empty()) {
    throw std::invalid_argument("give exactly one of --init FILE or --init-points \"x,y ...\"");
  }
  if (!options.init_file.empty()) return read_first_polygon(options.init_file);
  try {
    return parse_points_list(options.init_points);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("--init-points: ") + e.what());
  }
}

TrackSummary run_track(const TrackRunOptions& options, std::ostream& log) {
  if (options.output.empty()) throw std::invalid_argument("--output is required");
  if (options.max_frames < 0) {
    throw std::invalid_argument("--max-frames must be >= 0, got " +
                                std::to_string(options.max_frames));
  }
  // Before anything is read or written: no output may overwrite an input or another output.
  std::vector<NamedPath> inputs = {{"INPUT", options.input}};
  if (!options.init_file.empty()) inputs.push_back({"--init", options.init_file});
  std::vector<NamedPath> outputs = {{"-o", options.output}};
  if (!options.csv.empty()) outputs.push_back({"--csv", options.csv});
  if (!options.video.empty()) outputs.push_back({"--video", options.video});
  std::vector<NamedPath> output_folders;
  if (!options.frames_out.empty()) output_folders.push_back({"--frames-out", options.frames_out});
  check_no_overwrite(inputs, outputs, output_folders);

  const Polygon initial = load_initial_polygon(options);
  Tracker tracker(options.tracker);
  const StopSignalScope signal_scope(options.handle_signals);
  std::unique_ptr<FrameSource> source = open_frame_source(options.input);
  // Every output is classified and opened before the first frame (a folder, a missing folder or
  // a video name without a container fails here); none replaces an old file before commit().
  OutputSet output_set;
  OutputFile& results = output_set.add_file(options.output);
  OutputFile* csv = options.csv.empty() ? nullptr : &output_set.add_file(options.csv);
  VideoOutput* video =
      options.video.empty() ? nullptr : &output_set.add_video(options.video, source->fps());
  FrameFolderOutput* frames_out =
      options.frames_out.empty() ? nullptr : &output_set.add_frame_folder(options.frames_out);

  cv::Mat frame;
  if (!source->read(&frame)) throw std::runtime_error(options.input + ": no frames");
  try {
    tracker.init(frame, initial);
  } catch (const std::invalid_argument& e) {
    // Named by where the polygon came from: a file's content (exit 1) or the command line (2).
    const std::string detail = std::string("initial polygon: ") + e.what() + " (first frame " +
                               source->current_name() + ")";
    if (!options.init_file.empty()) throw std::runtime_error(options.init_file + ":1: " + detail);
    throw std::invalid_argument("--init-points: " + detail);
  }
  const bool annotate = !options.video.empty() || !options.frames_out.empty();
  tracker.set_keep_debug(annotate);

  if (csv) write_csv_header(csv->stream());
  results.stream() << format_polygon_line(initial) << '\n';
  output_set.end_record();
  TrackSummary summary;
  summary.frames = 1;
  summary.expected_frames = source->frame_count();
  double total_ms = 0.0;
  ProgressBar progress(log, "tracking", source->frame_count(), !options.quiet);

  auto emit_annotation = [&](const cv::Mat& image, int index) {
    if (video) video->write(image);
    if (frames_out) frames_out->write(index, image);
  };

  {
    if (annotate) {
      TrackResult first;
      first.boundary = initial;
      emit_annotation(annotate_frame(frame, {}, first, "frame 1: initial boundary"), 1);
    }
    while (options.max_frames <= 0 || summary.frames < options.max_frames) {
      if (g_stop_signal != 0 || output_set.reader_gone()) break;
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
      if (!bad.empty()) {
        if (options.on_bad_frame == BadFramePolicy::kStop) {
          throw std::runtime_error(bad + " (frame " + std::to_string(summary.frames) +
                                   "; --on-bad-frame=stop)");
        }
        ++summary.bad_frames;
        if (!options.quiet) log << '\n';
        log << "scbt: warning: " << printable(bad) << " (frame " << summary.frames
            << "); boundary held\n";
        r = TrackResult();
        r.boundary = tracker.boundary();
        r.held = true;
        results.stream() << format_polygon_line(r.boundary) << '\n';
        if (csv) write_csv_row(csv->stream(), summary.frames, r, "bad frame: " + bad);
        output_set.end_record();
        progress.update(summary.frames);
        continue;
      }
      ++summary.tracked;
      summary.held += r.held ? 1 : 0;
      summary.mean_line_ms += r.line_ms;
      summary.mean_grouping_ms += r.grouping_ms;
      summary.mean_vertices += r.num_vertices;
      summary.mean_edges += r.num_edges;
      total_ms += r.total_ms();
      results.stream() << format_polygon_line(r.boundary) << '\n';
      if (csv) write_csv_row(csv->stream(), summary.frames, r, frame_note(r, frame.size()));
      if (annotate) {
        char status[160];
        std::snprintf(status, sizeof(status), "frame %d  %s  %.2f ms  cost %.4f  sim %.3f",
                      summary.frames, r.held ? "HELD" : "tracked", r.total_ms(), r.cost,
                      r.area_similarity);
        emit_annotation(annotate_frame(frame, tracker.debug(), r, status), summary.frames);
      }
      output_set.end_record();
      progress.update(summary.frames);
    }
  }
  progress.finish(summary.frames);
  summary.stop_signal = g_stop_signal;
  if (summary.stop_signal == 0 && output_set.reader_gone()) summary.stop_signal = SIGPIPE;

  if (summary.tracked > 0) {
    const double n = summary.tracked;
    summary.mean_line_ms /= n;
    summary.mean_grouping_ms /= n;
    summary.mean_vertices /= n;
    summary.mean_edges /= n;
    summary.fps = total_ms > 0 ? 1000.0 * n / total_ms : 0.0;
  }
  output_set.commit();
  if (summary.stop_signal == SIGPIPE) {
    log << "scbt: warning: the reader of a streamed output went away (EPIPE) after frame "
        << summary.frames << "; the other outputs hold frames 1.." << summary.frames << "\n";
  } else if (summary.stop_signal != 0) {
    log << "scbt: warning: interrupted by " << signal_name(summary.stop_signal) << " after frame "
        << summary.frames;
    if (summary.expected_frames > 0) log << " of " << summary.expected_frames;
    log << "; " << printable(options.output) << " holds frames 1.." << summary.frames << "\n";
  }
  if (summary.bad_frames > 0) {
    log << "scbt: warning: " << summary.bad_frames << " bad frame(s) reported and held\n";
  }
  const bool cut_short = options.max_frames > 0 && summary.frames >= options.max_frames;
  if (summary.stop_signal == 0 && !cut_short && summary.expected_frames > 0 &&
      summary.frames < summary.expected_frames) {
    // Frames lost without a trace (no timestamp gap) cannot be placed: later lines may be early.
    // They count as bad frames (exit code 3).
    log << "scbt: warning: " << printable(options.input) << " gave " << summary.frames << " of the "
        << summary.expected_frames
        << " frames it announced (it ended early, or frames were lost in decoding)\n";
    summary.bad_frames += summary.expected_frames - summary.frames;
  }
  if (!options.quiet) log << format_summary(summary);
  return summary;
}

std::string format_summary(const TrackSummary& s) {
  char text[512];
  std::snprintf(text, sizeof(text),
                "frames %d (tracked %d, held %d)\n"
                "mean line time %.3f ms, grouping time %.3f ms, %.1f fps\n"
                "mean graph vertices %.1f, edges %.1f\n",
                s.frames, s.tracked, s.held, s.mean_line_ms, s.mean_grouping_ms, s.fps,
                s.mean_vertices, s.mean_edges);
  return text;
}

}  // namespace scbt
