#include "scbt/app/interactive_run.h"

#include <algorithm>
#include <cstdlib>
#include <deque>
#include <functional>
#include <memory>
#include <opencv2/highgui.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <vector>

#include "scbt/app/frame_writers.h"
#include "scbt/app/sequence_runner.h"
#include "scbt/geometry/polygon_io.h"
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

// What the window shows and the summary counts, kept up to date by the runner.
class WindowState : public FrameWriter {
 public:
  explicit WindowState(InteractiveSummary* summary) : summary_(summary) {}
  void write(const TrackedFrame& f) override {
    last = *f.result;
    show_debug = !f.initial;
    summary_->frames = f.number;
    if (f.initial) return;
    ++summary_->tracked;
    summary_->held += last.held ? 1 : 0;
    total_ms += last.total_ms();
    const double instant = last.total_ms() > 0 ? 1000.0 / last.total_ms() : 0.0;
    fps_estimate = fps_estimate == 0.0 ? instant : 0.9 * fps_estimate + 0.1 * instant;
  }

  TrackResult last;
  bool show_debug = false;
  double fps_estimate = 0.0;
  double total_ms = 0.0;

 private:
  InteractiveSummary* summary_;
};

// The annotated video shows the first initialisation only; re-initialisations replace no frame.
class FirstInitialOnly : public FrameWriter {
 public:
  explicit FirstInitialOnly(FrameWriter* inner) : inner_(inner) {}
  void write(const TrackedFrame& f) override {
    if (f.initial && seen_initial_) return;
    seen_initial_ = seen_initial_ || f.initial;
    inner_->write(f);
  }
  void commit() override { inner_->commit(); }

 private:
  FrameWriter* inner_;
  bool seen_initial_ = false;
};

void check_display() {
  // Without a display the GUI toolkit would abort the process; fail with a message instead.
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((display == nullptr || *display == '\0') && (wayland == nullptr || *wayland == '\0')) {
    throw std::runtime_error("the interactive window needs a display: DISPLAY is not set");
  }
}

// The window: the frame, the segments, the boundary (or the polygon being drawn), status.
cv::Mat draw_window(const cv::Mat& frame, const Tracker& tracker, const WindowState& state,
                    const InteractiveSession& session, bool initialised, int frame_number) {
  TrackResult shown = state.last;
  if (session.mode() == InteractiveMode::kDrawing) shown.boundary.clear();
  char status[160];
  if (initialised) {
    std::snprintf(status, sizeof(status), "frame %d %s %.0f fps [%s]", frame_number,
                  state.last.held ? "HELD" : "tracked", state.fps_estimate,
                  mode_name(session.mode()));
  } else {
    std::snprintf(status, sizeof(status), "frame %d  [%s]", frame_number,
                  mode_name(session.mode()));
  }
  static const TrackDebug kNoDebug;
  cv::Mat canvas =
      annotate_frame(frame, state.show_debug ? tracker.debug() : kNoDebug, shown, status);
  if (session.mode() == InteractiveMode::kDrawing) {
    const Polygon& draft = session.draft();
    for (size_t i = 0; i + 1 < draft.size(); ++i) {
      cv::line(canvas, draft[i], draft[i + 1], cv::Scalar(0, 255, 0), 2, cv::LINE_AA);
    }
    for (const Point& p : draft) cv::circle(canvas, p, 3, cv::Scalar(0, 255, 0), -1);
  }
  put_text(&canvas, session.message(), {8, canvas.rows - 10});
  return canvas;
}

// Feeds the mouse clicks and the key to the session; returns whether it asked to initialise.
bool handle_input(MouseEvents* mouse, int key, InteractiveSession* session) {
  std::vector<SessionAction> actions;
  while (!mouse->events.empty()) {
    const auto [event, point] = mouse->events.front();
    mouse->events.pop_front();
    actions.push_back(event == cv::EVENT_LBUTTONDOWN ? session->on_left_click(point)
                                                     : session->on_middle_click());
  }
  actions.push_back(session->on_key(key));
  return std::find(actions.begin(), actions.end(), SessionAction::kInitialise) != actions.end();
}

std::string video_caption(const TrackedFrame& f, const WindowState& state) {
  if (f.initial) return "frame 1: initial boundary";
  char text[128];
  std::snprintf(text, sizeof(text), "frame %d %s %.0f fps", f.number,
                f.result->held ? "HELD" : "tracked", state.fps_estimate);
  return text;
}

// The files the session writes: results, the raw input and the annotated video, when asked.
struct InteractiveOutputs {
  InteractiveOutputs(const InteractiveRunOptions& options, const Tracker* tracker,
                     const WindowState* state, double fps)
      : results(options.track.output) {
    if (!options.save_input.empty()) {
      input_video = std::make_unique<InputVideoWriter>(options.save_input, fps);
    }
    if (!options.track.video.empty()) {
      annotated = std::make_unique<AnnotationWriter>(
          tracker, options.track.video, fps, "",
          [state](const TrackedFrame& f) { return video_caption(f, *state); });
      annotated_once = std::make_unique<FirstInitialOnly>(annotated.get());
    }
  }

  ResultsWriter results;
  std::unique_ptr<InputVideoWriter> input_video;
  std::unique_ptr<AnnotationWriter> annotated;
  std::unique_ptr<FirstInitialOnly> annotated_once;
};

// Tracks the next frame when the session wants one.
void advance(SequenceRunner* runner, InteractiveSession* session, std::ostream& log) {
  if (!runner->step()) {
    session->end_of_input();
    log << "interactive: end of input after " << runner->frames() << " frames\n" << std::flush;
    return;
  }
  if (session->mode() != InteractiveMode::kRunning) {
    log << "interactive: stepped to frame " << runner->frames() << '\n' << std::flush;
  }
  session->frame_done();
}

// How long to wait for input: paced playback while running, else a relaxed poll.
int wait_ms(const InteractiveRunOptions& options, const InteractiveSession& session,
            bool initialised) {
  const bool busy = session.wants_frame() && !session.input_ended() && initialised;
  if (!busy) return 30;
  return options.playback_fps > 0 ? std::max(1, static_cast<int>(1000.0 / options.playback_fps))
                                  : 1;
}

void finish_summary(int frames, const WindowState& state, InteractiveSummary* summary,
                    std::ostream& log) {
  summary->frames = frames;
  summary->fps = state.total_ms > 0 ? 1000.0 * summary->tracked / state.total_ms : 0.0;
  log << "interactive: " << summary->frames << " frames, " << summary->tracked << " tracked, "
      << summary->held << " held, " << summary->initialisations << " initialisations, "
      << summary->fps << " fps\n";
}

bool window_closed(const std::string& name) {
  return cv::getWindowProperty(name, cv::WND_PROP_AUTOSIZE) < 0;
}

// The window's event loop: track while running, draw, and take the user's keys and polygons
// until quit or the window is closed.
void run_window(const InteractiveRunOptions& options, SequenceRunner* runner,
                const Tracker& tracker, const WindowState& state, const cv::Mat& frame,
                bool has_init, const std::function<void(const Polygon&)>& initialise,
                const bool* initialised, std::ostream& log) {
  cv::namedWindow(options.window_name, cv::WINDOW_AUTOSIZE | cv::WINDOW_GUI_NORMAL);
  MouseEvents mouse;
  cv::setMouseCallback(options.window_name, on_mouse, &mouse);
  InteractiveSession session(has_init);
  log << "interactive: window '" << options.window_name << "' open, mode "
      << mode_name(session.mode()) << '\n'
      << std::flush;
  InteractiveMode logged_mode = session.mode();
  while (session.mode() != InteractiveMode::kQuit) {
    if (*initialised && session.wants_frame() && !session.input_ended()) {
      advance(runner, &session, log);
    }
    cv::imshow(options.window_name,
               draw_window(frame, tracker, state, session, *initialised, runner->frames()));
    if (handle_input(&mouse, cv::waitKeyEx(wait_ms(options, session, *initialised)), &session)) {
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
      log << "interactive: mode " << mode_name(logged_mode) << " at frame " << runner->frames()
          << '\n'
          << std::flush;
    }
    if (session.mode() != InteractiveMode::kQuit && window_closed(options.window_name)) break;
  }
  cv::destroyWindow(options.window_name);
  cv::waitKey(1);
}

}  // namespace

InteractiveSummary run_interactive(const InteractiveRunOptions& options, std::ostream& log) {
  const TrackRunOptions& track = options.track;
  check_display();
  const bool has_init = !track.init_file.empty() || !track.init_points.empty();
  const Polygon initial = has_init ? load_initial_polygon(track) : Polygon{};
  BdspPolygonTracker bdsp{Tracker(track.tracker)};
  bdsp.tracker().set_keep_debug(true);
  std::unique_ptr<FrameSource> source = open_frame_source(track.input);
  const double input_fps = source->fps() > 0 ? source->fps() : 30.0;

  InteractiveSummary summary;
  WindowState state(&summary);
  InteractiveOutputs out(options, &bdsp.tracker(), &state, input_fps);
  SequenceRunOptions run_options;
  run_options.max_frames = track.max_frames;
  SequenceRunner runner(&bdsp, source.get(),
                        {out.input_video.get(), &state, &out.results, out.annotated_once.get()},
                        run_options);
  const cv::Mat& frame = runner.read_first(track.input);
  summary.frames = 1;
  if (out.input_video) {
    TrackedFrame first;  // the input video has it even if no polygon is ever drawn
    first.number = 1;
    first.image = &frame;
    out.input_video->write(first);
  }

  bool initialised = false;
  auto initialise = [&](const Polygon& polygon) {
    runner.start(polygon);
    initialised = true;
    ++summary.initialisations;
    log << "interactive: boundary of " << polygon.size() << " vertices set on frame "
        << runner.frames() << '\n'
        << std::flush;
  };
  if (has_init) {
    try {
      initialise(initial);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("initial polygon: ") + e.what());
    }
  }

  run_window(options, &runner, bdsp.tracker(), state, frame, has_init, initialise, &initialised,
             log);
  runner.commit();
  if (!track.csv.empty()) log << "interactive: --csv is not written in interactive mode\n";
  finish_summary(runner.frames(), state, &summary, log);
  return summary;
}

}  // namespace scbt
