// The body of `scbt track --interactive` and `scbt track --camera N`: a window shows each frame
// with the detected segments and the boundary; the user draws the initial polygon with the mouse
// and steps, runs, re-initialises or quits with keys. The window loop is run_interactive(); the
// editing and key logic is InteractiveSession, which needs no display and is unit-tested.
#pragma once

#include <ostream>
#include <string>

#include "scbt/app/track_run.h"
#include "scbt/geometry/polygon.h"

namespace scbt {

enum class InteractiveMode {
  kDrawing,  // placing polygon vertices on the frozen frame
  kPaused,   // tracking initialised, waiting for space (run) or s (step)
  kRunning,  // tracking every frame as it comes
  kQuit,
};

// What the window loop must do after an input event.
enum class SessionAction {
  kNone,        // nothing beyond redrawing
  kInitialise,  // take_polygon() is complete: initialise the tracker on the shown frame
  kQuit,
};

// Key codes as cv::waitKeyEx reports them (low byte for ASCII keys).
constexpr int kKeyEscape = 27;
constexpr int kKeyEnter = 13;
constexpr int kKeyLineFeed = 10;  // GTK reports Return as '\n'
constexpr int kKeyBackspace = 8;
constexpr int kKeySpace = ' ';

// The polygon editing and run/step/re-initialise state machine of the interactive window.
//   drawing: left click adds a vertex, Backspace removes the last one, middle click or Enter
//            closes the polygon (it must be a usable boundary, else a message says why);
//   paused:  space runs, s steps one frame, r redraws; running: space pauses, s steps, r redraws;
//   Esc (or q) quits from any mode.
class InteractiveSession {
 public:
  // With an initial polygon (from --init) the session starts paused, else drawing.
  explicit InteractiveSession(bool start_with_polygon);

  InteractiveMode mode() const { return mode_; }
  const Polygon& draft() const { return draft_; }  // vertices placed so far (drawing mode)
  const std::string& message() const { return message_; }

  SessionAction on_left_click(const Point& p);
  SessionAction on_middle_click();
  SessionAction on_key(int key);

  // The closed polygon after kInitialise; the draft is cleared.
  Polygon take_polygon();
  // The loop reports whether the tracker accepted the polygon: paused on success, back to
  // drawing (keeping the draft) with the reason otherwise.
  void polygon_accepted();
  void polygon_rejected(const std::string& reason);

  // True when the loop should read and track the next frame now.
  bool wants_frame() const { return mode_ == InteractiveMode::kRunning || step_pending_; }
  // The loop tracked one frame: a pending step is done (and the session pauses).
  void frame_done();
  // The input has no more frames: pause (or stay drawing) with a message.
  void end_of_input();
  bool input_ended() const { return input_ended_; }

 private:
  SessionAction close_polygon();

  InteractiveMode mode_;
  Polygon draft_;
  Polygon closed_;
  std::string message_;
  bool step_pending_ = false;
  bool input_ended_ = false;
};

struct InteractiveRunOptions {
  // input, init (optional here), output (optional), video (annotated), csv, max_frames, tracker.
  TrackRunOptions track;
  std::string save_input;  // optional video of the raw input frames as read
  std::string window_name = "scbt";
  // Frames per second to pace playback of files when running (0: as fast as tracking allows).
  double playback_fps = 0.0;
};

struct InteractiveSummary {
  int frames = 0;  // frames read (shown), the first one included
  int tracked = 0;
  int held = 0;
  int initialisations = 0;
  double fps = 0.0;  // tracked frames per second of tracking time
};

// Opens the window and runs the session until Esc. Writes the results file (one polygon line
// per frame from the first initialisation on; a re-initialisation replaces that frame's line),
// the annotated video and the input video when asked, when the session ends. Events go to `log`.
InteractiveSummary run_interactive(const InteractiveRunOptions& options, std::ostream& log);

}  // namespace scbt
