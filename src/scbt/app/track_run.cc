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
#include "scbt/io/atomic_file.h"
#include "scbt/io/frame_source.h"
#include "scbt/render/annotate.h"

namespace scbt {
namespace fs = std::filesystem;
namespace {

// Set by the handler; read once per frame by the tracking loop.
volatile std::sig_atomic_t g_stop_signal = 0;

extern "C" void on_stop_signal(int signal_number) { g_stop_signal = signal_number; }

// Installs on_stop_signal for SIGINT and SIGTERM for its lifetime, then restores the old handlers.
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
  }
  ~StopSignalScope() {
    if (!enabled_) return;
    sigaction(SIGINT, &old_int_, nullptr);
    sigaction(SIGTERM, &old_term_, nullptr);
  }
  StopSignalScope(const StopSignalScope&) = delete;
  StopSignalScope& operator=(const StopSignalScope&) = delete;

 private:
  bool enabled_;
  struct sigaction old_int_ {};
  struct sigaction old_term_ {};
};

const char* signal_name(int signal_number) {
  switch (signal_number) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    default:
      return "a signal";
  }
}

int video_fourcc(const std::string& path) {
  const std::string ext = fs::path(path).extension().string();
  if (ext == ".mp4" || ext == ".m4v") return cv::VideoWriter::fourcc('m', 'p', '4', 'v');
  return cv::VideoWriter::fourcc('M', 'J', 'P', 'G');
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
  const Polygon initial = load_initial_polygon(options);
  Tracker tracker(options.tracker);
  std::unique_ptr<FrameSource> source = open_frame_source(options.input);

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

  AtomicFile results(options.output);
  std::unique_ptr<AtomicFile> csv;
  if (!options.csv.empty()) {
    csv = std::make_unique<AtomicFile>(options.csv);
    write_csv_header(csv->stream());
  }
  std::unique_ptr<cv::VideoWriter> video;
  std::string video_temporary;
  if (!options.frames_out.empty()) fs::create_directories(options.frames_out);

  results.stream() << format_polygon_line(initial) << '\n';
  TrackSummary summary;
  summary.frames = 1;
  summary.expected_frames = source->frame_count();
  const StopSignalScope signal_scope(options.handle_signals);
  double total_ms = 0.0;
  ProgressBar progress(log, "tracking", source->frame_count(), !options.quiet);

  auto emit_annotation = [&](const cv::Mat& image, int index) {
    if (!options.video.empty()) {
      if (!video) {
        // The writer picks its container from the extension, so the temporary keeps it.
        const fs::path path(options.video);
        video_temporary = (path.parent_path() / (".tmp-" + path.filename().string())).string();
        const double fps = source->fps() > 0 ? source->fps() : 30.0;
        video = std::make_unique<cv::VideoWriter>(video_temporary, video_fourcc(options.video), fps,
                                                  image.size());
        if (!video->isOpened()) throw std::runtime_error(options.video + ": cannot write video");
      }
      video->write(image);
    }
    if (!options.frames_out.empty()) {
      char name[32];
      std::snprintf(name, sizeof(name), "%04d.jpg", index);
      const std::string path = (fs::path(options.frames_out) / name).string();
      if (!cv::imwrite(path, image)) throw std::runtime_error(path + ": cannot write image");
    }
  };

  try {
    if (annotate) {
      TrackResult first;
      first.boundary = initial;
      emit_annotation(annotate_frame(frame, {}, first, "frame 1: initial boundary"), 1);
    }
    while (options.max_frames <= 0 || summary.frames < options.max_frames) {
      if (g_stop_signal != 0) break;
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
        log << "scbt: warning: " << bad << " (frame " << summary.frames << "); boundary held\n";
        r = TrackResult();
        r.boundary = tracker.boundary();
        r.held = true;
        results.stream() << format_polygon_line(r.boundary) << '\n';
        if (csv) write_csv_row(csv->stream(), summary.frames, r, "bad frame: " + bad);
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
      progress.update(summary.frames);
    }
  } catch (...) {
    if (video) {
      video->release();
      std::remove(video_temporary.c_str());
    }
    throw;
  }
  progress.finish(summary.frames);
  summary.stop_signal = g_stop_signal;

  if (summary.tracked > 0) {
    const double n = summary.tracked;
    summary.mean_line_ms /= n;
    summary.mean_grouping_ms /= n;
    summary.mean_vertices /= n;
    summary.mean_edges /= n;
    summary.fps = total_ms > 0 ? 1000.0 * n / total_ms : 0.0;
  }
  results.commit();
  if (csv) csv->commit();
  if (video) {
    video->release();
    fs::rename(video_temporary, options.video);
  }
  if (summary.stop_signal != 0) {
    log << "scbt: warning: interrupted by " << signal_name(summary.stop_signal) << " after frame "
        << summary.frames;
    if (summary.expected_frames > 0) log << " of " << summary.expected_frames;
    log << "; " << options.output << " holds frames 1.." << summary.frames << "\n";
  }
  const bool cut_short = options.max_frames > 0 && summary.frames >= options.max_frames;
  if (summary.stop_signal == 0 && !cut_short && summary.expected_frames > 0 &&
      summary.frames < summary.expected_frames) {
    log << "scbt: warning: " << options.input << " ended after frame " << summary.frames
        << " of the " << summary.expected_frames << " it announced\n";
  }
  if (summary.bad_frames > 0) {
    log << "scbt: warning: " << summary.bad_frames << " bad frame(s) reported and held\n";
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
