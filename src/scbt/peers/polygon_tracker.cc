#include "scbt/peers/polygon_tracker.h"

#include <stdexcept>

#include "scbt/geometry/polygon_io.h"
#include "scbt/peers/csrt_tracker.h"
#include "scbt/peers/ecc_tracker.h"
#include "scbt/peers/klt_tracker.h"
#include "scbt/peers/rrc_tracker.h"
#include "scbt/tracker/frame_checks.h"

namespace scbt {
namespace {

// The floor every tracker must beat: the initial polygon, never moved.
class StaticTracker : public PolygonTracker {
 public:
  void init(const cv::Mat& frame, const Polygon& polygon) override {
    cv::Mat gray;
    to_gray(frame, &gray);  // same frame checks as every other tracker
    check_boundary_polygon(polygon);
    polygon_ = polygon;
  }
  TrackResult track(const cv::Mat&) override {
    TrackResult result;
    result.boundary = polygon_;
    result.held = true;
    return result;
  }

 private:
  Polygon polygon_;
};

}  // namespace

std::vector<std::string> polygon_tracker_names() {
  return {"scbt", "ecc", "klt", "csrt", "rrc", "static"};
}

std::string canonical_polygon_tracker_name(const std::string& name) {
  return name == "bdsp" ? "scbt" : name;
}

std::unique_ptr<PolygonTracker> make_polygon_tracker(const std::string& name,
                                                     const TrackerOptions& options) {
  if (canonical_polygon_tracker_name(name) == "scbt")
    return std::make_unique<BdspPolygonTracker>(Tracker(options));
  if (name == "ecc") return std::make_unique<EccTracker>();
  if (name == "klt") return std::make_unique<KltTracker>();
  if (name == "csrt") return std::make_unique<CsrtTracker>();
  if (name == "rrc") {
    // The same line detector and distance filter as scbt's tracker, so only the grouping differs.
    options.check();
    RrcTrackerOptions rrc;
    rrc.detector = options.detector;
    rrc.filter_distance = options.filter_distance;
    return std::make_unique<RrcTracker>(rrc);
  }
  if (name == "static") return std::make_unique<StaticTracker>();
  throw std::invalid_argument("unknown tracker '" + name + "'");
}

}  // namespace scbt
