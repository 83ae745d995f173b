#include "scbt_ros/latest_slot.h"

#include <gtest/gtest.h>

#include <future>
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

TEST(LatestSlot, PutNeverWaitsForABusyConsumer) {
  LatestSlot<int> slot;
  std::promise<void> taken;
  std::promise<void> producer_done;
  std::thread consumer([&] {
    EXPECT_EQ(slot.take(), 0);
    taken.set_value();
    // Busy with item 0 until the producer has put everything: if put() waited for the consumer,
    // neither would go on (the test would hang and time out).
    producer_done.get_future().wait();
  });
  slot.put(0);
  taken.get_future().wait();
  for (int i = 1; i <= 1000; ++i) slot.put(i);
  producer_done.set_value();
  consumer.join();
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
