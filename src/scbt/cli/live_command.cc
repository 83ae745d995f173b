// `scbt track --camera N` and `scbt track VIDEO --interactive`: the live/interactive window mode of
// the track command (src/scbt/app/interactive_run.h does the work).
#include <iostream>
#include <stdexcept>
#include <string>

#include "scbt/app/interactive_run.h"
#include "scbt/cli/commands.h"

namespace scbt::cli {

std::shared_ptr<LiveOptions> add_live_options(CLI::App* command) {
  auto live = std::make_shared<LiveOptions>();
  command
      ->add_option("--camera", live->camera,
                   "Track live from camera N in an interactive window (instead of INPUT)")
      ->check(CLI::NonNegativeNumber);
  command->add_flag("--interactive", live->interactive,
                    "Show a window: draw the initial polygon with left clicks (middle click or "
                    "Enter closes it), space runs/pauses, s steps, r redraws, Esc quits");
  command->add_option("--save-input", live->save_input,
                      "With --interactive/--camera: also save the input frames as a video");
  command->add_option("--playback-fps", live->playback_fps,
                      "With --interactive: pace a video file to this rate (0: as fast as "
                      "tracking allows)");
  return live;
}

bool run_live_if_requested(const LiveOptions& live, const TrackRunOptions& track, int* exit_code) {
  if (live.camera >= 0 && !track.input.empty()) {
    throw std::invalid_argument("give either INPUT or --camera N, not both");
  }
  if (live.camera < 0 && track.input.empty()) {
    throw std::invalid_argument("INPUT is required (a video, an image folder) or --camera N");
  }
  if (live.camera < 0 && !live.interactive) {
    if (!live.save_input.empty()) {
      throw std::invalid_argument("--save-input needs --interactive or --camera");
    }
    return false;
  }
  InteractiveRunOptions options;
  options.track = track;
  if (live.camera >= 0) options.track.input = std::to_string(live.camera);
  options.save_input = live.save_input;
  options.playback_fps = live.playback_fps;
  if (!track.init_box.empty() || track.start_frame != 1) {
    throw std::invalid_argument(
        "--init-box and --start-frame are not available in the interactive "
        "mode");
  }
  if (!options.track.frames_out.empty()) {
    throw std::invalid_argument("--frames-out is not available in the interactive mode");
  }
  run_interactive(options, std::cerr);
  *exit_code = 0;
  return true;
}

}  // namespace scbt::cli
