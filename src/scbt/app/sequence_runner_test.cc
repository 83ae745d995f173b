#include "scbt/app/sequence_runner.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace scbt {
namespace {

// Frames from a list; an empty Mat stands for a frame that cannot be decoded.
class ListSource : public FrameSource {
 public:
  explicit ListSource(std::vector<cv::Mat> frames) : frames_(std::move(frames)) {}
  bool read(cv::Mat* frame) override {
    if (next_ >= frames_.size()) return false;
    const cv::Mat& f = frames_[next_++];
    if (f.empty()) throw std::runtime_error("frame " + std::to_string(next_) + " is corrupt");
    *frame = f;
    return true;
  }
  int frame_count() const override { return static_cast<int>(frames_.size()); }
  std::string current_name() const override { return "frame " + std::to_string(next_); }

 private:
  std::vector<cv::Mat> frames_;
  size_t next_ = 0;
};

// Moves the boundary one pixel right per frame; rejects frames of another size like Tracker.
class ShiftTracker : public PolygonTracker {
 public:
  void init(const cv::Mat& frame, const Polygon& polygon) override {
    size_ = frame.size();
    boundary_ = polygon;
  }
  TrackResult track(const cv::Mat& frame) override {
    if (frame.size() != size_) throw std::invalid_argument("frame size changed");
    for (Point& p : boundary_) p.x += 1;
    TrackResult r;
    r.boundary = boundary_;
    return r;
  }

 private:
  cv::Size size_;
  Polygon boundary_;
};

// Records what it was given, to check order, numbering and the commit.
class Recorder : public FrameWriter {
 public:
  void write(const TrackedFrame& f) override {
    numbers.push_back(f.number);
    initial.push_back(f.initial);
    bad.push_back(!f.bad.empty());
    first_x.push_back(f.result->boundary.front().x);
    states.push_back(f.result->state);
  }
  void commit() override { ++commits; }
  std::vector<int> numbers;
  std::vector<bool> initial, bad;
  std::vector<double> first_x;
  std::vector<TrackState> states;
  int commits = 0;
};

const Polygon kSquare = {{10, 10}, {30, 10}, {30, 30}, {10, 30}};

cv::Mat frame(int cols = 64) { return cv::Mat(48, cols, CV_8UC1, cv::Scalar(0)); }

TEST(SequenceRunner, WritesEveryFrameInOrderAndCommitsOnce) {
  ListSource source({frame(), frame(), frame(), frame()});
  ShiftTracker tracker;
  Recorder first, second;
  RunStatistics stats;
  SequenceRunner runner(&tracker, &source, {&first, nullptr, &second, &stats});
  runner.read_first("list");
  runner.start(kSquare);
  runner.run();
  EXPECT_EQ(first.numbers, (std::vector<int>{1, 2, 3, 4}));
  EXPECT_EQ(first.initial, (std::vector<bool>{true, false, false, false}));
  EXPECT_EQ(first.first_x, (std::vector<double>{10, 11, 12, 13}));
  EXPECT_EQ(second.numbers, first.numbers);
  EXPECT_EQ(first.commits, 1);
  EXPECT_EQ(second.commits, 1);
  EXPECT_EQ(stats.frames, 4);
  EXPECT_EQ(stats.tracked, 3);
  EXPECT_EQ(runner.frames(), 4);
}

TEST(SequenceRunner, NoFramesNamesTheInput) {
  ListSource source({});
  ShiftTracker tracker;
  SequenceRunner runner(&tracker, &source, {});
  try {
    runner.read_first("empty.avi");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("empty.avi"), std::string::npos);
  }
}

TEST(SequenceRunner, HoldKeepsTheBoundaryOverBadFrames) {
  // Frame 3 cannot be decoded, frame 4 has another size: both held, tracking goes on at 5.
  ListSource source({frame(), frame(), cv::Mat(), frame(80), frame()});
  ShiftTracker tracker;
  Recorder record;
  RunStatistics stats;
  SequenceRunOptions options;
  options.on_bad_frame = BadFramePolicy::kHold;
  SequenceRunner runner(&tracker, &source, {&record, &stats}, options);
  runner.read_first("list");
  runner.start(kSquare);
  runner.run();
  EXPECT_EQ(record.numbers, (std::vector<int>{1, 2, 3, 4, 5}));
  EXPECT_EQ(record.bad, (std::vector<bool>{false, false, true, true, false}));
  EXPECT_EQ(record.first_x, (std::vector<double>{10, 11, 11, 11, 12}));
  EXPECT_EQ(stats.bad, 2);
  EXPECT_EQ(stats.tracked, 2);
  EXPECT_EQ(record.states[2], TrackState::kUncertain);  // not seen by the tracker
}

TEST(SequenceRunner, StartFrameSkipsAndNumbersByTheInput) {
  // Frame 2 (skipped) cannot be decoded: no error, it is not tracked.
  ListSource source({frame(), cv::Mat(), frame(), frame(), frame()});
  ShiftTracker tracker;
  Recorder record;
  SequenceRunOptions options;
  options.start_frame = 3;
  options.max_frames = 2;  // counted from the start frame
  SequenceRunner runner(&tracker, &source, {&record}, options);
  runner.read_first("list");
  runner.start(kSquare);
  runner.run();
  EXPECT_EQ(record.numbers, (std::vector<int>{3, 4}));
  EXPECT_EQ(runner.frames(), 2);
}

TEST(SequenceRunner, StartFrameBeyondTheInputNamesBoth) {
  ListSource source({frame(), frame()});
  ShiftTracker tracker;
  SequenceRunOptions options;
  options.start_frame = 3;
  SequenceRunner runner(&tracker, &source, {}, options);
  try {
    runner.read_first("list");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--start-frame 3 is beyond the input: list has 2"),
              std::string::npos)
        << e.what();
  }
}

TEST(SequenceRunner, StopPolicyNamesTheFrameAndCommitsNothing) {
  ListSource source({frame(), frame(), frame(80)});
  ShiftTracker tracker;
  Recorder record;
  SequenceRunOptions options;
  options.on_bad_frame = BadFramePolicy::kStop;
  SequenceRunner runner(&tracker, &source, {&record}, options);
  runner.read_first("list");
  runner.start(kSquare);
  try {
    runner.run();
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("frame 3"), std::string::npos) << e.what();
  }
  EXPECT_EQ(record.commits, 0);
}

TEST(SequenceRunner, RaisePolicyLetsTheTrackersErrorThrough) {
  ListSource source({frame(), frame(80)});
  ShiftTracker tracker;
  SequenceRunner runner(&tracker, &source, {});
  runner.read_first("list");
  runner.start(kSquare);
  EXPECT_THROW(runner.run(), std::invalid_argument);
}

TEST(SequenceRunner, StopsAtMaxFramesAndOnTheStopFlag) {
  ListSource source({frame(), frame(), frame(), frame(), frame()});
  ShiftTracker tracker;
  Recorder record;
  bool stop = false;
  SequenceRunOptions options;
  options.max_frames = 4;
  options.stop = [&stop] { return stop; };
  SequenceRunner runner(&tracker, &source, {&record}, options);
  runner.read_first("list");
  runner.start(kSquare);
  EXPECT_TRUE(runner.step());
  stop = true;
  EXPECT_FALSE(runner.step());
  stop = false;
  EXPECT_TRUE(runner.step());
  EXPECT_TRUE(runner.step());
  EXPECT_FALSE(runner.step());  // max_frames counts the initial frame
  EXPECT_EQ(record.numbers, (std::vector<int>{1, 2, 3, 4}));
}

TEST(SequenceRunner, ReinitialisationIsWrittenAsAnInitialFrame) {
  ListSource source({frame(), frame(), frame()});
  ShiftTracker tracker;
  Recorder record;
  SequenceRunner runner(&tracker, &source, {&record});
  runner.read_first("list");
  runner.start(kSquare);
  ASSERT_TRUE(runner.step());
  runner.start({{0, 0}, {5, 0}, {5, 5}, {0, 5}});
  ASSERT_TRUE(runner.step());
  EXPECT_EQ(record.numbers, (std::vector<int>{1, 2, 2, 3}));
  EXPECT_EQ(record.initial, (std::vector<bool>{true, false, true, false}));
  EXPECT_EQ(record.first_x, (std::vector<double>{10, 11, 0, 1}));
}

}  // namespace
}  // namespace scbt
