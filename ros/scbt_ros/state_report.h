// What the node reports per frame: the `~state` message, one JSON object per frame
// (std_msgs/String) with every statistic and timing, and the tracking state as a standard
// diagnostic_msgs/DiagnosticStatus for /diagnostics (rqt_runtime_monitor, diagnostic_aggregator).
#pragma once

#include <diagnostic_msgs/DiagnosticStatus.h>

#include <cstdint>
#include <string>

#include "scbt/depth/boundary_3d.h"
#include "scbt/tracker/tracker.h"

namespace scbt::ros_node {

enum class FrameEvent {
  kWaiting,      // no initial boundary yet: nothing tracked
  kInitialised,  // the frame the (re-)initialisation was applied to: boundary = the given polygon
  kTracked,      // tracked from the previous frame
  kFailed,       // the tracker rejected the frame (see the log): nothing published on ~boundary
};

std::string to_string(FrameEvent event);

struct FrameReport {
  FrameEvent event = FrameEvent::kWaiting;
  std::uint64_t frame = 0;          // frames taken by the worker so far, this one included
  std::uint64_t dropped_total = 0;  // frames replaced by a newer one before they were tracked
  std::uint64_t dropped_since_last = 0;
  std::uint64_t missed_total = 0;       // gaps in the images' header.seq: lost before the node
  double latency_ms = 0.0;              // from the callback receiving the frame to publishing it
  const TrackResult* result = nullptr;  // kTracked only
  const Boundary3d* boundary_3d = nullptr;  // with depth
  double depth_ms = 0.0;                    // the lift to 3-D
  std::string reason{};                     // kFailed: why (the tracker's error message)
};

// {"event": ..., "frame": ..., "state": ..., "confidence": ..., "held": ..., "timings_ms": {...},
// "dropped_frames": ..., "missed_frames": ..., "reason": ... (failed frames)} (docs/ros.md lists
// the fields).
std::string state_json(const FrameReport& report);

// The frame's state as a diagnostic named `name`: level OK while tracking (or just initialised),
// WARN while uncertain or waiting for an initial boundary, ERROR when lost or when the frame was
// not tracked; message the state, values event, state, confidence, held, frame, dropped_frames,
// missed_frames and latency_ms.
diagnostic_msgs::DiagnosticStatus diagnostic_status(const FrameReport& report,
                                                    const std::string& name);

}  // namespace scbt::ros_node
