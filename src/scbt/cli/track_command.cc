#include <iostream>

#include "scbt/app/track_run.h"
#include "scbt/cli/commands.h"

namespace scbt::cli {

void add_track_command(CLI::App& app, int* exit_code) {
  auto options = std::make_shared<TrackRunOptions>();
  auto detector = std::make_shared<std::string>("edlines");
  CLI::App* command = app.add_subcommand(
      "track", "Track a closed boundary through a video, an image folder or a camera");
  command
      ->add_option("INPUT", options->input,
                   "Video file, folder of numbered images, or camera index")
      ->required();
  command->add_option("--init", options->init_file,
                      "Polygon file whose first line is the initial boundary: n x1 y1 ... xn yn");
  command->add_option("--init-points", options->init_points,
                      "Initial boundary inline: \"x1,y1 x2,y2 ...\"");
  command
      ->add_option("-o,--output", options->output, "Results file: one polygon line per input frame")
      ->required();
  command->add_option("--csv", options->csv, "Per-frame statistics and timings (CSV)");
  command->add_option("--video", options->video, "Annotated output video (.avi or .mp4)");
  command->add_option("--frames-out", options->frames_out, "Folder for annotated frames");
  command->add_option("--max-frames", options->max_frames, "Stop after this many frames (0: all)");
  command->add_flag("-q,--quiet", options->quiet, "No progress bar and no summary");
  add_tracker_options(command, &options->tracker, detector.get());
  command->callback([options, detector, exit_code] {
    options->tracker.detector.kind = parse_line_detector_kind(*detector);
    run_track(*options, std::cerr);
    *exit_code = 0;
  });
}

}  // namespace scbt::cli
