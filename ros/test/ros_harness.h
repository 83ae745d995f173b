// What the ROS node tests need around them: a rosmaster of their own on a free loopback port,
// child processes (the node) started and stopped, and received messages waited for.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace scbt::ros_test {

// A TCP port on 127.0.0.1 that was free a moment ago (bound to port 0, then released).
int free_loopback_port();

// A child process with its stdout and stderr sent to `log_path`.
class ChildProcess {
 public:
  ChildProcess() = default;
  // Starts argv[0] (searched on PATH) with the environment of this process. Throws
  // std::runtime_error when it cannot be started.
  ChildProcess(const std::vector<std::string>& argv, const std::string& log_path);
  ~ChildProcess();  // stops it (SIGINT, then SIGKILL) if still running
  ChildProcess(ChildProcess&& other) noexcept;
  ChildProcess& operator=(ChildProcess&& other) noexcept;

  bool running();
  // Waits up to `timeout` for it to exit; its exit code, -signal when killed by one, or nullopt
  // when still running.
  std::optional<int> wait(std::chrono::milliseconds timeout);
  // SIGINT, then SIGKILL after `grace`; the exit code as wait() gives it.
  int stop(std::chrono::milliseconds grace = std::chrono::milliseconds(3000));
  const std::string& log_path() const { return log_path_; }
  std::string log() const;  // what it printed so far

 private:
  pid_t pid_ = -1;
  std::optional<int> exit_code_;
  std::string log_path_;
};

// Messages from a subscriber callback (any thread), taken by the test thread.
template <typename Message>
class Inbox {
 public:
  void push(const Message& message) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      messages_.push_back(message);
    }
    arrived_.notify_all();
  }
  // The oldest message not taken yet, waiting up to `timeout` for one.
  std::optional<Message> pop(std::chrono::milliseconds timeout) {
    std::unique_lock<std::mutex> lock(mutex_);
    if (!arrived_.wait_for(lock, timeout, [this] { return !messages_.empty(); })) {
      return std::nullopt;
    }
    Message out = messages_.front();
    messages_.pop_front();
    return out;
  }
  void clear() {
    std::lock_guard<std::mutex> lock(mutex_);
    messages_.clear();
  }

 private:
  std::mutex mutex_;
  std::condition_variable arrived_;
  std::deque<Message> messages_;
};

// Polls `done` every 10 ms until it returns true or `timeout` passes; returns its last value.
template <typename Predicate>
bool wait_until(Predicate done, std::chrono::milliseconds timeout) {
  const auto end = std::chrono::steady_clock::now() + timeout;
  while (!done()) {
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return true;
}

// True when `program` is an executable on PATH.
bool on_path(const std::string& program);

}  // namespace scbt::ros_test
