// Shared by the tracker's scene tests: one line describing a run, for failure messages.
#pragma once

#include <sstream>
#include <string>
#include <vector>

#include "scbt/synthetic/scene.h"
#include "scbt/tracker/tracker.h"

namespace scbt {

// "k:state/confidence %/error px" for every frame after the initial one (results[0]).
inline std::string describe_run(const std::vector<TrackResult>& results,
                                const std::vector<SceneFrame>& frames) {
  std::ostringstream out;
  for (size_t k = 1; k < results.size(); ++k) {
    const TrackResult& r = results[k];
    out << k << ":" << to_string(r.state)[0] << "/" << static_cast<int>(100 * r.confidence) << "/"
        << static_cast<int>(mean_boundary_distance(r.boundary, frames[k].truth)) << " ";
  }
  return out.str();
}

}  // namespace scbt
