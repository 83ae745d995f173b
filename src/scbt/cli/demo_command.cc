#include <iostream>
#include <stdexcept>

#include "scbt/app/demo_run.h"
#include "scbt/app/depth_demo_run.h"
#include "scbt/cli/commands.h"

namespace scbt::cli {

void add_demo_command(CLI::App& app, int* exit_code) {
  auto options = std::make_shared<DemoOptions>();
  auto shape = std::make_shared<std::string>(to_string(options->scene.shape));
  auto no_video = std::make_shared<bool>(false);
  auto depth = std::make_shared<DepthDemoOptions>();
  auto with_depth = std::make_shared<bool>(false);
  CLI::App* command = app.add_subcommand(
      "demo",
      "Render a synthetic clip (a textureless outline moving, rotating and scaling over clutter "
      "and noise), track it from its known first outline and report the error against the truth; "
      "with --depth an RGB-D clip of a bowl, its rim lifted to 3-D and scored");
  command->add_option("--out", options->out_dir, "Output folder (--depth: scbt-demo-depth)")
      ->capture_default_str();
  command->add_option("--frames", options->frames, "Clip length in frames (--depth: 30)")
      ->capture_default_str();
  command->add_flag("--depth", *with_depth,
                    "An RGB-D clip of a bowl (colour and 16-bit depth PNGs with a sensor's noise, "
                    "mixed pixels and holes), tracked, its rim lifted to 3-D and scored against "
                    "the truth; prints the `scbt track --depth` command for the clip");
  command->add_option("--distance", depth->distance, "--depth: the bowl's distance (m)")
      ->capture_default_str();
  command->add_option("--seed", options->scene.seed, "Seed of the clutter, noise and shape")
      ->capture_default_str();
  command->add_option("--shape", *shape, "Tracked outline: rim (a cup rim), box or polygon")
      ->capture_default_str();
  command->add_option("--noise", options->scene.noise_sigma, "Gaussian noise sigma (grey levels)")
      ->capture_default_str();
  command->add_option("--clutter", options->scene.clutter_strokes, "Number of clutter strokes")
      ->capture_default_str();
  command->add_flag("--no-video", *no_video, "Do not write the annotated demo.avi");
  command->add_flag("-q,--quiet", options->quiet, "No progress bar and no summary");
  // -o is `track`'s results file; this command writes a folder.
  command->add_option("-o")->group("")->each([](const std::string&) {
    throw std::invalid_argument(
        "demo writes a folder: give it as --out DIR (-o is track's results file)");
  });
  auto flags = add_tracker_options(command);
  command->callback([command, options, flags, shape, no_video, depth, with_depth, exit_code] {
    if (flags->apply(&options->tracker)) {
      *exit_code = kExitOk;
      return;
    }
    if (*with_depth) {
      for (const char* name : {"--shape", "--noise", "--clutter", "--no-video"})
        if (command->count(name) > 0)
          throw std::invalid_argument(std::string(name) + " does not apply to demo --depth");
      if (command->count("--out") > 0) depth->out_dir = options->out_dir;
      if (command->count("--frames") > 0) depth->frames = options->frames;
      if (command->count("--seed") > 0) depth->seed = options->scene.seed;
      depth->quiet = options->quiet;
      depth->tracker = options->tracker;
      const DepthDemoSummary summary = run_depth_demo(*depth, std::cerr);
      if (!depth->quiet) std::cout << format_depth_demo_summary(summary) << std::flush;
      *exit_code = 0;
      return;
    }
    if (command->count("--distance") > 0) throw std::invalid_argument("--distance needs --depth");
    options->scene.shape = parse_scene_shape(*shape);
    options->video = !*no_video;
    const DemoSummary summary = run_demo(*options, std::cerr);
    if (!options->quiet) std::cout << format_demo_summary(summary) << std::flush;
    *exit_code = 0;
  });
}

}  // namespace scbt::cli
