#include "scbt/app/interactive_run.h"

#include <algorithm>
#include <cstdlib>
#include <deque>
#include <memory>
#include <opencv2/highgui.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>
#include <stdexcept>
#include <vector>

#include "scbt/geometry/polygon_io.h"
#include "scbt/io/atomic_file.h"
#include "scbt/io/frame_source.h"
#include "scbt/render/annotate.h"

namespace scbt {

InteractiveSession::InteractiveSession(bool start_with_polygon)
    : mode_(start_with_polygon ? InteractiveMode::kPaused : InteractiveMode::kDrawing) {
  message_ = start_with_polygon ? "space: run  s: step  r: redraw  Esc: quit"
                                : "left click: add vertex  middle click/Enter: close polygon";
}

SessionAction InteractiveSession::on_left_click(const Point& p) {
  if (mode_ != InteractiveMode::kDrawing) return SessionAction::kNone;
  draft_.push_back(p);
  message_ = std::to_string(draft_.size()) + " vertices; middle click or Enter closes";
  return SessionAction::kNone;
}

SessionAction InteractiveSession::on_middle_click() {
  if (mode_ != InteractiveMode::kDrawing) return SessionAction::kNone;
  return close_polygon();
}

SessionAction InteractiveSession::close_polygon() {
  try {
    check_boundary_polygon(draft_);
  } catch (const std::invalid_argument& e) {
    message_ = std::string("cannot close: ") + e.what();
    return SessionAction::kNone;
  }
  closed_ = draft_;
  return SessionAction::kInitialise;
}

SessionAction InteractiveSession::on_key(int key) {
  if (key < 0) return SessionAction::kNone;
  const int low = key & 0xff;
  if (low == kKeyEscape || low == 'q') {
    mode_ = InteractiveMode::kQuit;
    return SessionAction::kQuit;
  }
  if (mode_ == InteractiveMode::kDrawing) {
    if (low == kKeyEnter || low == kKeyLineFeed) return close_polygon();
    if (low == kKeyBackspace && !draft_.empty()) {
      draft_.pop_back();
      message_ = std::to_string(draft_.size()) + " vertices";
    }
    return SessionAction::kNone;
  }
  if (mode_ == InteractiveMode::kQuit) return SessionAction::kQuit;
  switch (low) {
    case kKeySpace:
      if (input_ended_) break;
      mode_ =
          mode_ == InteractiveMode::kRunning ? InteractiveMode::kPaused : InteractiveMode::kRunning;
      message_ = mode_ == InteractiveMode::kRunning ? "running (space: pause)" : "paused";
      break;
    case 's':
      if (input_ended_) break;
      mode_ = InteractiveMode::kPaused;
      step_pending_ = true;
      message_ = "step";
      break;
    case 'r':
      mode_ = InteractiveMode::kDrawing;
      step_pending_ = false;
      draft_.clear();
      message_ = "draw a new polygon: left clicks, then middle click or Enter";
      break;
    default:
      break;
  }
  return SessionAction::kNone;
}

Polygon InteractiveSession::take_polygon() {
  Polygon polygon = std::move(closed_);
  closed_.clear();
  return polygon;
}

void InteractiveSession::polygon_accepted() {
  draft_.clear();
  mode_ = InteractiveMode::kPaused;
  message_ = input_ended_ ? "end of input (Esc: quit)" : "space: run  s: step  r: redraw";
}

void InteractiveSession::polygon_rejected(const std::string& reason) {
  mode_ = InteractiveMode::kDrawing;
  message_ = "polygon rejected: " + reason;
}

void InteractiveSession::frame_done() {
  if (step_pending_) {
    step_pending_ = false;
    mode_ = InteractiveMode::kPaused;
  }
}

void InteractiveSession::end_of_input() {
  input_ended_ = true;
  step_pending_ = false;
  if (mode_ == InteractiveMode::kRunning) mode_ = InteractiveMode::kPaused;
  message_ = "end of input (r: redraw, Esc: quit)";
}

namespace {

struct MouseEvents {
  std::deque<std::pair<int, Point>> events;  // (cv::MouseEventTypes, position)
};

void on_mouse(int event, int x, int y, int /*flags*/, void* user) {
  if (event == cv::EVENT_LBUTTONDOWN || event == cv::EVENT_MBUTTONDOWN) {
    static_cast<MouseEvents*>(user)->events.emplace_back(event, Point(x, y));
  }
}

int fourcc_for(const std::string& path) {
  const auto dot = path.rfind('.');
  const std::string ext = dot == std::string::npos ? "" : path.substr(dot);
  if (ext == ".mp4" || ext == ".m4v") return cv::VideoWriter::fourcc('m', 'p', '4', 'v');
  return cv::VideoWriter::fourcc('M', 'J', 'P', 'G');
}

// A video file opened on the first frame written.
class LazyVideo {
 public:
  LazyVideo(std::string path, double fps) : path_(std::move(path)), fps_(fps) {}
  void write(const cv::Mat& image) {
    if (path_.empty()) return;
    if (!writer_.isOpened()) {
      if (!writer_.open(path_, fourcc_for(path_), fps_, image.size(), image.channels() != 1)) {
        throw std::runtime_error(path_ + ": cannot write video");
      }
    }
    writer_.write(image);
  }

 private:
  std::string path_;
  double fps_;
  cv::VideoWriter writer_;
};

void put_text(cv::Mat* canvas, const std::string& text, cv::Point at) {
  cv::putText(*canvas, text, at, cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(0, 0, 0), 3,
              cv::LINE_AA);
  cv::putText(*canvas, text, at, cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(255, 255, 255), 1,
              cv::LINE_AA);
}

const char* mode_name(InteractiveMode mode) {
  switch (mode) {
    case InteractiveMode::kDrawing:
      return "drawing";
    case InteractiveMode::kPaused:
      return "paused";
    case InteractiveMode::kRunning:
      return "running";
    case InteractiveMode::kQuit:
      return "quit";
  }
  return "";
}

}  // namespace

InteractiveSummary run_interactive(const InteractiveRunOptions& options, std::ostream& log) {
  const TrackRunOptions& track = options.track;
  // Without a display the GUI toolkit would abort the process; fail with a message instead.
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((display == nullptr || *display == '\0') && (wayland == nullptr || *wayland == '\0')) {
    throw std::runtime_error("the interactive window needs a display: DISPLAY is not set");
  }
  const bool has_init = !track.init_file.empty() || !track.init_points.empty();
  const Polygon initial = has_init ? load_initial_polygon(track) : Polygon{};
  Tracker tracker(track.tracker);
  tracker.set_keep_debug(true);
  std::unique_ptr<FrameSource> source = open_frame_source(track.input);
  const double input_fps = source->fps() > 0 ? source->fps() : 30.0;

  cv::Mat frame;
  if (!source->read(&frame)) throw std::runtime_error(track.input + ": no frames");
  InteractiveSummary summary;
  summary.frames = 1;

  LazyVideo input_video(options.save_input, input_fps);
  LazyVideo annotated_video(track.video, input_fps);
  input_video.write(frame);

  std::vector<std::string> lines;  // results: one line per frame from the first initialisation
  int first_line_frame = 0;        // 1-based frame of lines[0]
  auto set_line = [&](int frame_number, const Polygon& polygon) {
    if (lines.empty()) first_line_frame = frame_number;
    const size_t index = static_cast<size_t>(frame_number - first_line_frame);
    if (index < lines.size()) {
      lines[index] = format_polygon_line(polygon);
    } else {
      lines.resize(index);  // frames shown before any initialisation stay empty (never happens
                            // with the current flow: drawing freezes the input)
      lines.push_back(format_polygon_line(polygon));
    }
  };

  TrackResult last;
  bool show_debug = false;
  bool initialised = false;
  double fps_estimate = 0.0;
  double total_ms = 0.0;

  InteractiveSession session(has_init);
  auto initialise = [&](const Polygon& polygon) {
    tracker.init(frame, polygon);
    last = TrackResult{};
    last.boundary = polygon;
    show_debug = false;
    set_line(summary.frames, polygon);
    if (!initialised) {
      annotated_video.write(annotate_frame(frame, {}, last, "frame 1: initial boundary"));
    }
    initialised = true;
    ++summary.initialisations;
    log << "interactive: boundary of " << polygon.size() << " vertices set on frame "
        << summary.frames << '\n'
        << std::flush;
  };
  if (has_init) {
    try {
      initialise(initial);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("initial polygon: ") + e.what());
    }
  }

  cv::namedWindow(options.window_name, cv::WINDOW_AUTOSIZE | cv::WINDOW_GUI_NORMAL);
  MouseEvents mouse;
  cv::setMouseCallback(options.window_name, on_mouse, &mouse);
  log << "interactive: window '" << options.window_name << "' open, mode "
      << mode_name(session.mode()) << '\n'
      << std::flush;

  InteractiveMode logged_mode = session.mode();
  while (session.mode() != InteractiveMode::kQuit) {
    if (initialised && session.wants_frame() && !session.input_ended()) {
      cv::Mat next;  // a failed read must not clear the frame on screen
      if ((track.max_frames > 0 && summary.frames >= track.max_frames) || !source->read(&next)) {
        session.end_of_input();
        log << "interactive: end of input after " << summary.frames << " frames\n" << std::flush;
      } else {
        frame = next;
        ++summary.frames;
        input_video.write(frame);
        last = tracker.track(frame);
        show_debug = true;
        ++summary.tracked;
        summary.held += last.held ? 1 : 0;
        total_ms += last.total_ms();
        const double instant = last.total_ms() > 0 ? 1000.0 / last.total_ms() : 0.0;
        fps_estimate = fps_estimate == 0.0 ? instant : 0.9 * fps_estimate + 0.1 * instant;
        set_line(summary.frames, last.boundary);
        char text[128];
        std::snprintf(text, sizeof(text), "frame %d %s %.0f fps", summary.frames,
                      last.held ? "HELD" : "tracked", fps_estimate);
        annotated_video.write(annotate_frame(frame, tracker.debug(), last, text));
        if (session.mode() != InteractiveMode::kRunning) {
          log << "interactive: stepped to frame " << summary.frames << '\n' << std::flush;
        }
        session.frame_done();
      }
    }

    // The window: the frame, the segments, the boundary (or the polygon being drawn), status.
    TrackResult shown = last;
    if (session.mode() == InteractiveMode::kDrawing) shown.boundary.clear();
    char status[160];
    if (initialised) {
      std::snprintf(status, sizeof(status), "frame %d %s %.0f fps [%s]", summary.frames,
                    last.held ? "HELD" : "tracked", fps_estimate, mode_name(session.mode()));
    } else {
      std::snprintf(status, sizeof(status), "frame %d  [%s]", summary.frames,
                    mode_name(session.mode()));
    }
    static const TrackDebug kNoDebug;
    cv::Mat canvas = annotate_frame(frame, show_debug ? tracker.debug() : kNoDebug, shown, status);
    if (session.mode() == InteractiveMode::kDrawing) {
      const Polygon& draft = session.draft();
      for (size_t i = 0; i + 1 < draft.size(); ++i) {
        cv::line(canvas, draft[i], draft[i + 1], cv::Scalar(0, 255, 0), 2, cv::LINE_AA);
      }
      for (const Point& p : draft) cv::circle(canvas, p, 3, cv::Scalar(0, 255, 0), -1);
    }
    put_text(&canvas, session.message(), {8, canvas.rows - 10});
    cv::imshow(options.window_name, canvas);

    const bool busy = session.wants_frame() && !session.input_ended() && initialised;
    int delay = 30;
    if (busy) {
      delay = options.playback_fps > 0
                  ? std::max(1, static_cast<int>(1000.0 / options.playback_fps))
                  : 1;
    }
    const int key = cv::waitKeyEx(delay);
    std::vector<SessionAction> actions;
    while (!mouse.events.empty()) {
      const auto [event, point] = mouse.events.front();
      mouse.events.pop_front();
      actions.push_back(event == cv::EVENT_LBUTTONDOWN ? session.on_left_click(point)
                                                       : session.on_middle_click());
    }
    actions.push_back(session.on_key(key));
    for (SessionAction action : actions) {
      if (action != SessionAction::kInitialise) continue;
      const Polygon polygon = session.take_polygon();
      try {
        initialise(polygon);
        session.polygon_accepted();
      } catch (const std::invalid_argument& e) {
        session.polygon_rejected(e.what());
        log << "interactive: polygon rejected: " << e.what() << '\n' << std::flush;
      }
    }
    if (session.mode() != logged_mode) {
      logged_mode = session.mode();
      log << "interactive: mode " << mode_name(logged_mode) << " at frame " << summary.frames
          << '\n'
          << std::flush;
    }
    if (session.mode() != InteractiveMode::kQuit &&
        cv::getWindowProperty(options.window_name, cv::WND_PROP_AUTOSIZE) < 0) {
      break;  // the window was closed
    }
  }
  cv::destroyWindow(options.window_name);
  cv::waitKey(1);

  if (!track.output.empty()) {
    AtomicFile results(track.output);
    for (const std::string& line : lines) results.stream() << line << '\n';
    results.commit();
  }
  if (!track.csv.empty()) log << "interactive: --csv is not written in interactive mode\n";
  summary.fps = total_ms > 0 ? 1000.0 * summary.tracked / total_ms : 0.0;
  log << "interactive: " << summary.frames << " frames, " << summary.tracked << " tracked, "
      << summary.held << " held, " << summary.initialisations << " initialisations, " << summary.fps
      << " fps\n";
  return summary;
}

}  // namespace scbt
