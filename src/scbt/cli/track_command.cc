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

namespace {

// --depth and its companions (issue 20, docs/depth.md), in their own group of the help.
void add_depth_options(CLI::App* command, TrackDepthOptions* depth) {
  const std::string group = "3-D from an aligned depth image (docs/depth.md)";
  command
      ->add_option("--depth", depth->depth,
                   "DEPTH_INPUT: a folder of 16-bit depth PNGs numbered like INPUT's frames, or a "
                   "TUM RGB-D folder (rgb.txt, depth.txt; INPUT is then that folder too)")
      ->group(group);
  command
      ->add_option("--intrinsics", depth->intrinsics,
                   "Pinhole intrinsics of the colour camera: fx,fy,cx,cy (pixels)")
      ->group(group);
  command
      ->add_option("--camera-info", depth->camera_info,
                   "Or the intrinsics and distortion from a ROS camera_info YAML or an OpenCV "
                   "calibration file")
      ->group(group);
  command
      ->add_option("--depth-scale", depth->lift.depth_scale,
                   "Metres per depth unit (TUM RGB-D: 0.0002); refused when no 16-bit value "
                   "1..65535 would be a valid depth (0.1..10 m)")
      ->capture_default_str()
      ->group(group);
  command
      ->add_option("--points3d", depth->points3d,
                   "Per-frame CSV: frame,valid,x,y,z,nx,ny,nz,radius,rms,n_valid,n_samples "
                   "(rim centroid and normal, metres, camera frame; valid 0 while lost or "
                   "without enough depth). Required with --depth")
      ->group(group);
  command
      ->add_option("--boundary3d", depth->boundary3d,
                   "Per-frame line \"n x1 y1 z1 ... xn yn zn\" of the rim's 3-D points")
      ->group(group);
}

}  // namespace

void add_track_command(CLI::App& app, int* exit_code) {
  auto options = std::make_shared<TrackRunOptions>();
  auto on_bad_frame = std::make_shared<std::string>("hold");
  CLI::App* command = app.add_subcommand(
      "track", "Track a closed boundary through a video, an image folder or a camera");
  command->add_option("INPUT", options->input,
                      "Video file, folder of numbered images, or camera index (or --camera N)");
  command->add_option("--init", options->init_file,
                      "Polygon file whose first line is the initial boundary: n x1 y1 ... xn yn; "
                      "with one line per frame of INPUT (a ground-truth file), line N is the "
                      "boundary on --start-frame N");
  command->add_option("--init-points", options->init_points,
                      "Initial boundary inline: \"x1,y1 x2,y2 ...\"");
  command->add_option("--init-box", options->init_box,
                      "Initial box x,y,w,h (integer pixels, each within +-1000000; w, h > 0) "
                      "instead of a polygon: the most salient closed boundary inside it is "
                      "tracked (not with --init/--init-points)");
  command
      ->add_option("--start-frame", options->start_frame,
                   "Track from frame N, counted from 1 = the first frame of INPUT (whatever "
                   "number its file name carries); the initial boundary is on frame N (line N "
                   "of an --init file with one line per frame, else its first line) and the "
                   "results hold one line per frame from N; an error if INPUT has fewer frames")
      ->capture_default_str();
  command->add_option(
      "-o,--output", options->output,
      "Results file: one polygon line per frame from --start-frame on (a run needs at least "
      "one of -o, --csv, --video, --frames-out, --points3d, unless --interactive/--camera)");
  command->add_option("--csv", options->csv,
                      "Per-frame CSV: frame, held, state (tracking/uncertain/lost), confidence "
                      "(0-1), statistics, timings and a note (docs/loss-handling.md)");
  command->add_option("--video", options->video,
                      "Annotated output video (.avi or .mp4); the boundary is green while "
                      "tracking, amber when uncertain, red and labelled when lost");
  command->add_option("--frames-out", options->frames_out, "Folder for annotated frames");
  command->add_option("--max-frames", options->max_frames, "Stop after this many frames (0: all)");
  command
      ->add_option("--on-bad-frame", *on_bad_frame,
                   "A frame that cannot be decoded or changes size: hold (report it, keep the "
                   "boundary, go on; exit code 3) or stop (fail)")
      ->check(CLI::IsMember({"hold", "stop"}));
  command->add_flag("-q,--quiet", options->quiet,
                    "No progress and no summary (progress: a bar on a terminal, else a line at "
                    "every tenth of the frames that will run)");
  add_depth_options(command, &options->depth);
  auto flags = add_tracker_options(command);
  auto live = add_live_options(command);
  command->callback([options, flags, live, on_bad_frame, exit_code] {
    if (flags->apply(&options->tracker)) {
      *exit_code = kExitOk;
      return;
    }
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
