#include "scbt/testing/test_dataset.h"

#include <cstdio>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

#include "scbt/geometry/polygon_io.h"

namespace scbt {

void write_synthetic_sequence(const std::filesystem::path& root, const std::string& name,
                              SceneShape shape, Point start, Point shift, std::uint32_t seed,
                              int frames) {
  SceneOptions scene;
  scene.seed = seed;
  scene.shape = shape;
  scene.size = {320, 240};
  scene.object_size = 45.0;
  Pose pose;
  pose.translation = start;
  const std::vector<SceneFrame> clip = render_clip(scene, linear_motion_path(pose, shift, frames));
  const std::filesystem::path folder = root / "OriginalVideosAVI" / name;
  std::filesystem::create_directories(folder);
  std::filesystem::create_directories(root / "GroundTruthByPolygons");
  std::ofstream truth(root / "GroundTruthByPolygons" / (name + "_TrackingGroundTruth.txt"));
  for (int i = 0; i < frames; ++i) {
    char file[16];
    std::snprintf(file, sizeof(file), "%04d.png", i + 1);
    if (!cv::imwrite((folder / file).string(), clip[i].image)) {
      throw std::runtime_error("cannot write " + (folder / file).string());
    }
    truth << format_polygon_line(clip[i].truth) << '\n';
  }
  if (!truth) throw std::runtime_error("cannot write the ground truth of " + name);
}

}  // namespace scbt
