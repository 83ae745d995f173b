#include "scbt_ros/latest_slot.h"

#include <gtest/gtest.h>

#include <thread>

namespace scbt::ros_node {
namespace {

TEST(LatestSlot, KeepsOnlyTheNewestAndCountsTheReplaced) {
  LatestSlot<int> slot;
  slot.put(1);
  slot.put(2);
  slot.put(3);
  EXPECT_EQ(slot.dropped(), 2u);
  EXPECT_EQ(slot.take(), 3);
  slot.put(4);
  EXPECT_EQ(slot.take(), 4);
  EXPECT_EQ(slot.dropped(), 2u);
}

TEST(LatestSlot, PutNeverWaitsForASlowConsumer) {
  LatestSlot<int> slot;
  std::thread consumer([&] {
    // Takes one item, then dawdles while the producer goes on.
    EXPECT_EQ(slot.take(), 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  });
  slot.put(0);
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  const auto start = std::chrono::steady_clock::now();
  for (int i = 1; i <= 1000; ++i) slot.put(i);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  consumer.join();
  EXPECT_LT(seconds, 0.15);  // far below the consumer's 200 ms: nothing waited for it
  EXPECT_EQ(slot.dropped(), 999u);
  EXPECT_EQ(slot.take(), 1000);
}

TEST(LatestSlot, CloseWakesAWaitingTake) {
  LatestSlot<int> slot;
  std::thread consumer([&] { EXPECT_FALSE(slot.take().has_value()); });
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  slot.close();
  consumer.join();
}

}  // namespace
}  // namespace scbt::ros_node
