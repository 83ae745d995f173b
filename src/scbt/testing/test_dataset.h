// Test support: small datasets in the public layout (OriginalVideosAVI/<Seq>/0001.png…,
// GroundTruthByPolygons/<Seq>_TrackingGroundTruth.txt), rendered in code.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "scbt/synthetic/scene.h"

namespace scbt {

// Renders `frames` 320x240 frames of `shape` (object size 45 px) starting at `start` and moving
// by `shift` per frame, and writes them with their ground truth under `root`. Throws
// std::runtime_error if a file cannot be written.
void write_synthetic_sequence(const std::filesystem::path& root, const std::string& name,
                              SceneShape shape, Point start, Point shift, std::uint32_t seed,
                              int frames);

}  // namespace scbt
