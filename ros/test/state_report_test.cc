// The frame's state as a standard diagnostic (for /diagnostics).
#include "scbt_ros/state_report.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace scbt::ros_node {
namespace {

std::map<std::string, std::string> values(const diagnostic_msgs::DiagnosticStatus& status) {
  std::map<std::string, std::string> out;
  for (const auto& pair : status.values) out[pair.key] = pair.value;
  return out;
}

TEST(DiagnosticStatus, LevelFollowsTheTrackingState) {
  using diagnostic_msgs::DiagnosticStatus;
  TrackResult result;
  result.confidence = 0.875;
  FrameReport report{FrameEvent::kTracked};
  report.result = &result;
  report.frame = 12;
  report.dropped_total = 3;

  result.state = TrackState::kTracking;
  DiagnosticStatus status = diagnostic_status(report, "/scbt: boundary tracking");
  EXPECT_EQ(status.name, "/scbt: boundary tracking");
  EXPECT_EQ(status.level, DiagnosticStatus::OK);
  EXPECT_EQ(status.message, "tracking");
  EXPECT_EQ(values(status)["confidence"], "0.875");
  EXPECT_EQ(values(status)["frame"], "12");
  EXPECT_EQ(values(status)["dropped_frames"], "3");
  EXPECT_EQ(values(status)["state"], "tracking");

  result.state = TrackState::kUncertain;
  result.held = true;
  status = diagnostic_status(report, "n");
  EXPECT_EQ(status.level, DiagnosticStatus::WARN);
  EXPECT_EQ(status.message, "uncertain (held)");

  result.state = TrackState::kLost;
  EXPECT_EQ(diagnostic_status(report, "n").level, DiagnosticStatus::ERROR);

  EXPECT_EQ(diagnostic_status(FrameReport{FrameEvent::kWaiting}, "n").level,
            DiagnosticStatus::WARN);
  EXPECT_EQ(diagnostic_status(FrameReport{FrameEvent::kFailed}, "n").level,
            DiagnosticStatus::ERROR);
  const DiagnosticStatus initialised =
      diagnostic_status(FrameReport{FrameEvent::kInitialised}, "n");
  EXPECT_EQ(initialised.level, DiagnosticStatus::OK);
  EXPECT_EQ(values(initialised)["state"], "tracking");
  EXPECT_EQ(values(initialised).count("confidence"), 0u);
}

}  // namespace
}  // namespace scbt::ros_node
