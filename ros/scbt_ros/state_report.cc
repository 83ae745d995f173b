#include "scbt_ros/state_report.h"

#include <diagnostic_msgs/KeyValue.h>

#include <cstdio>
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
    out["visible"] = r->visible;
    out["from_memory"] = r->from_memory;
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

diagnostic_msgs::DiagnosticStatus diagnostic_status(const FrameReport& report,
                                                    const std::string& name) {
  using diagnostic_msgs::DiagnosticStatus;
  DiagnosticStatus status;
  status.name = name;
  const auto add = [&status](const std::string& key, const std::string& value) {
    diagnostic_msgs::KeyValue pair;
    pair.key = key;
    pair.value = value;
    status.values.push_back(pair);
  };
  const auto number = [](double value) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.3f", value);
    return std::string(text);
  };
  std::string state;
  switch (report.event) {
    case FrameEvent::kWaiting:
      status.level = DiagnosticStatus::WARN;
      status.message = "waiting for an initial boundary (~init, ~init_box)";
      break;
    case FrameEvent::kFailed:
      status.level = DiagnosticStatus::ERROR;
      status.message = "frame not tracked (see the log)";
      break;
    case FrameEvent::kInitialised:
      status.level = DiagnosticStatus::OK;
      state = to_string(TrackState::kTracking);
      status.message = "initialised";
      break;
    case FrameEvent::kTracked: {
      const TrackResult& r = *report.result;
      state = to_string(r.state);
      status.level = r.state == TrackState::kTracking    ? DiagnosticStatus::OK
                     : r.state == TrackState::kUncertain ? DiagnosticStatus::WARN
                                                         : DiagnosticStatus::ERROR;
      status.message = state + (r.held ? " (held)" : "");
      break;
    }
  }
  add("event", to_string(report.event));
  if (!state.empty()) add("state", state);
  if (report.result) {
    add("confidence", number(report.result->confidence));
    add("held", report.result->held ? "true" : "false");
  }
  add("frame", std::to_string(report.frame));
  add("dropped_frames", std::to_string(report.dropped_total));
  add("missed_frames", std::to_string(report.missed_total));
  add("latency_ms", number(report.latency_ms));
  return status;
}

}  // namespace scbt::ros_node
