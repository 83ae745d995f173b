// Shared by the EDLines stages (edlines*.cc): the per-pixel codes of the direction and edge maps.
#pragma once

#include <cstdint>
#include <cstdlib>

namespace scbt {
namespace edlines_maps {

// Edge direction of a pixel at or above the gradient threshold (0: not an edge candidate).
constexpr std::uint8_t kHorizontal = 1;  // |gx| < |gy|: the edge runs left-right
constexpr std::uint8_t kVertical = 2;    // |gx| >= |gy|: the edge runs up-down

// Edge map states.
constexpr std::uint8_t kAnchor = 1;
constexpr std::uint8_t kEdge = 2;

// Walking directions; the first two share child slot 0, the last two slot 1.
enum WalkDir { kLeft = 0, kUp = 1, kRight = 2, kDown = 3 };

inline bool adjacent(int p, int q, int width) {
  return std::abs(p / width - q / width) <= 1 && std::abs(p % width - q % width) <= 1;
}

}  // namespace edlines_maps
}  // namespace scbt
