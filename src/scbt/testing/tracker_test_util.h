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

// Tracks `frames` from the first frame's true outline: one result per frame, results[0] (the
// initial frame) a default one.
inline std::vector<TrackResult> track_from_truth(const std::vector<SceneFrame>& frames,
                                                 const TrackerOptions& options = {}) {
  Tracker tracker(options);
  tracker.init(frames[0].image, frames[0].truth);
  std::vector<TrackResult> results(1);
  for (size_t k = 1; k < frames.size(); ++k) results.push_back(tracker.track(frames[k].image));
  return results;
}

}  // namespace scbt
