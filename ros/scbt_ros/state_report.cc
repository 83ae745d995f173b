#include "scbt_ros/state_report.h"

#include <nlohmann/json.hpp>

namespace scbt::ros_node {

std::string to_string(FrameEvent event) {
  switch (event) {
    case FrameEvent::kWaiting:
      return "waiting_for_init";
    case FrameEvent::kInitialised:
      return "initialised";
    case FrameEvent::kTracked:
      return "tracked";
    case FrameEvent::kFailed:
      return "failed";
  }
  return "unknown";
}

std::string state_json(const FrameReport& report) {
  nlohmann::json out;
  out["event"] = to_string(report.event);
  out["frame"] = report.frame;
  out["dropped_frames"] = report.dropped_total;
  out["dropped_since_last"] = report.dropped_since_last;
  out["missed_frames"] = report.missed_total;
  if (report.event == FrameEvent::kFailed) out["reason"] = report.reason;
  nlohmann::json timings;
  timings["latency"] = report.latency_ms;
  if (const TrackResult* r = report.result) {
    out["state"] = to_string(r->state);
    out["confidence"] = r->confidence;
    out["held"] = r->held;
    out["recovered"] = r->recovered;
    out["reacquired"] = r->reacquired;
    out["cost"] = r->cost;
    out["area_similarity"] = r->area_similarity;
    timings["line"] = r->line_ms;
    timings["grouping"] = r->grouping_ms;
    timings["total"] = r->total_ms();
    timings["filter"] = r->stages.filter_ms;
    timings["graph"] = r->stages.graph_ms;
    timings["search"] = r->stages.search_ms;
    timings["choice"] = r->stages.choice_ms;
    timings["recovery"] = r->stages.recovery_ms;
  } else if (report.event == FrameEvent::kInitialised) {
    // A new track from a boundary the user gave: tracking, its confidence not measured.
    out["state"] = to_string(TrackState::kTracking);
    out["confidence"] = nullptr;
    out["held"] = false;
  }
  if (const Boundary3d* b = report.boundary_3d) {
    nlohmann::json depth;
    depth["valid"] = b->valid;
    depth["samples"] = b->n_samples;
    depth["samples_with_depth"] = b->n_valid;
    depth["plane_rms_m"] = b->rms;
    if (b->circle.found) depth["circle_radius_m"] = b->circle.radius;
    out["depth"] = depth;
    timings["depth"] = report.depth_ms;
  }
  out["timings_ms"] = timings;
  return out.dump();
}

}  // namespace scbt::ros_node
