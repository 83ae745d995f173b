#include "scbt_ros/reason_throttle.h"

#include <gtest/gtest.h>

#include <string>

namespace scbt::ros_node {
namespace {

TEST(ReasonThrottle, EachReasonOncePerPeriodAndADifferentOneAtOnce) {
  ReasonThrottle throttle(5.0);
  EXPECT_TRUE(throttle.allow("image has encoding '16UC1'", 100.0));
  EXPECT_FALSE(throttle.allow("image has encoding '16UC1'", 101.0));
  // Another bad image a second later is heard of.
  EXPECT_TRUE(throttle.allow("image has encoding 'mono16'", 101.0));
  EXPECT_TRUE(throttle.allow("frame size changed from 640x480 to 320x240", 102.0));
  EXPECT_FALSE(throttle.allow("image has encoding 'mono16'", 105.9));
  EXPECT_TRUE(throttle.allow("image has encoding '16UC1'", 105.0));
  EXPECT_FALSE(throttle.allow("image has encoding '16UC1'", 109.9));
  EXPECT_TRUE(throttle.allow("image has encoding '16UC1'", 110.0));
}

TEST(ReasonThrottle, EverDifferentReasonsAreBoundedPerPeriod) {
  ReasonThrottle throttle(5.0, 3);
  int logged = 0;
  for (int k = 0; k < 100; ++k) logged += throttle.allow("size " + std::to_string(k), 0.01 * k);
  EXPECT_EQ(logged, 3);
  // Once the remembered ones have aged out, new reasons are logged again.
  EXPECT_TRUE(throttle.allow("size 1000", 6.0));
  EXPECT_FALSE(throttle.allow("size 1000", 6.5));
}

}  // namespace
}  // namespace scbt::ros_node
