#include <iostream>
#include <string>

#include "scbt/app/track_run.h"
#include "scbt/cli/commands.h"
#include "scbt/io/output_target.h"

namespace scbt::cli {

int report_error(const std::string& message, int exit_code) {
  // Always one line, so logs and scripts can take the last line of stderr as the reason: a
  // trailing newline is dropped, any other control character (in a file name) shown escaped.
  std::string line = message;
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r' || line.back() == ' ')) {
    line.pop_back();
  }
  std::cerr << "scbt: error: " << printable(line) << std::endl;
  return exit_code;
}

void add_track_command(CLI::App& app, int* exit_code) {
  auto options = std::make_shared<TrackRunOptions>();
  auto detector = std::make_shared<std::string>("edlines");
  auto on_bad_frame = std::make_shared<std::string>("hold");
  CLI::App* command = app.add_subcommand(
      "track", "Track a closed boundary through a video, an image folder or a camera");
  command->add_option("INPUT", options->input,
                      "Video file, folder of numbered images, or camera index (or --camera N)");
  command->add_option("--init", options->init_file,
                      "Polygon file whose first line is the initial boundary: n x1 y1 ... xn yn");
  command->add_option("--init-points", options->init_points,
                      "Initial boundary inline: \"x1,y1 x2,y2 ...\"");
  command->add_option("-o,--output", options->output,
                      "Results file: one polygon line per input frame (required unless "
                      "--interactive/--camera)");
  command->add_option("--csv", options->csv, "Per-frame statistics and timings (CSV)");
  command->add_option("--video", options->video, "Annotated output video (.avi or .mp4)");
  command->add_option("--frames-out", options->frames_out, "Folder for annotated frames");
  command->add_option("--max-frames", options->max_frames, "Stop after this many frames (0: all)");
  command
      ->add_option("--on-bad-frame", *on_bad_frame,
                   "A frame that cannot be decoded or changes size: hold (report it, keep the "
                   "boundary, go on; exit code 3) or stop (fail)")
      ->check(CLI::IsMember({"hold", "stop"}));
  command->add_flag("-q,--quiet", options->quiet, "No progress bar and no summary");
  add_tracker_options(command, &options->tracker, detector.get());
  auto live = add_live_options(command);
  command
      ->add_option("--max-segments", options->tracker.max_segments,
                   "Bound on the work per frame: keep at most this many (the longest) segments "
                   "near the boundary; the CSV note says when it capped")
      ->capture_default_str();
  command->callback([options, detector, live, on_bad_frame, exit_code] {
    options->tracker.detector.kind = parse_line_detector_kind(*detector);
    if (run_live_if_requested(*live, *options, exit_code)) return;
    options->on_bad_frame = parse_bad_frame_policy(*on_bad_frame);
    const TrackSummary summary = run_track(*options, std::cerr);
    if (summary.stop_signal != 0) {
      *exit_code = kExitInterrupted + summary.stop_signal;
    } else if (summary.bad_frames > 0) {
      *exit_code = kExitBadFrames;
    } else {
      *exit_code = kExitOk;
    }
  });
}

}  // namespace scbt::cli
