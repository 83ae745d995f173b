// A one-item mailbox between the ROS callback and the tracking worker: the callback puts the
// newest frame and never waits for the tracker; a frame not yet taken when the next arrives is
// replaced and counted as dropped. So the callback queue is never held up longer than one frame
// and a slow tracker sees the newest frame, not a growing backlog.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <utility>

namespace scbt::ros_node {

template <typename Item>
class LatestSlot {
 public:
  // Stores `item`, replacing (and counting as dropped) one that was not taken yet.
  void put(Item item) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (item_) ++dropped_;
      item_ = std::move(item);
    }
    ready_.notify_one();
  }

  // Waits for an item and takes it; std::nullopt once close() was called.
  std::optional<Item> take() {
    std::unique_lock<std::mutex> lock(mutex_);
    ready_.wait(lock, [this] { return item_.has_value() || closed_; });
    if (closed_) return std::nullopt;
    std::optional<Item> out = std::move(item_);
    item_.reset();
    return out;
  }

  // Wakes take() for good (the worker's exit).
  void close() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      closed_ = true;
    }
    ready_.notify_all();
  }

  // Items replaced before they were taken, since construction.
  std::uint64_t dropped() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return dropped_;
  }

 private:
  mutable std::mutex mutex_;
  std::condition_variable ready_;
  std::optional<Item> item_;
  std::uint64_t dropped_ = 0;
  bool closed_ = false;
};

}  // namespace scbt::ros_node
