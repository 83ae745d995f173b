// The caller's frames stay the caller's: no call of the tracker writes into a frame it was given,
// and none keeps a view of one once it returns, whatever the order of init, init_from_box and
// track calls and whatever mix of grey, BGR and BGRA frames they get.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "scbt/tracker/frame_checks.h"
#include "scbt/tracker/tracker.h"

namespace scbt {
namespace {

// A filled irregular pentagon, bright on dark, moved by `step` pixels right and half that down.
Polygon pentagon(int step) {
  Polygon p{{100, 70}, {190, 80}, {215, 150}, {150, 190}, {85, 160}};
  for (Point& v : p) v += Point(step, 0.5 * step);
  return p;
}

cv::Mat render(const Polygon& polygon, int type) {
  cv::Mat image(240, 320, type, cv::Scalar::all(40));
  std::vector<cv::Point> pts;
  for (const Point& v : polygon) pts.emplace_back(cvRound(v.x), cvRound(v.y));
  cv::fillPoly(image, std::vector<std::vector<cv::Point>>{pts}, cv::Scalar::all(210), cv::LINE_8);
  return image;
}

// Every frame handed to a tracker, with a copy of what it held. The ledger's Mat is the only
// header on each frame's buffer, so a reference count above 1 means someone else kept one.
class FrameLedger {
 public:
  const cv::Mat& give(cv::Mat frame) {
    given_.push_back({frame, frame.clone()});
    return given_.back().frame;
  }
  void expect_untouched(const std::string& after) const {
    for (std::size_t i = 0; i < given_.size(); ++i) {
      const Given& g = given_[i];
      EXPECT_EQ(cv::norm(g.frame, g.pristine, cv::NORM_INF), 0.0)
          << "frame " << i + 1 << " was written into, after " << after;
      EXPECT_EQ(g.frame.u->refcount, 1) << "frame " << i + 1 << " is still held, after " << after;
    }
  }

 private:
  struct Given {
    cv::Mat frame, pristine;
  };
  std::vector<Given> given_;
};

enum class Call { kInit, kInitFromBox, kTrack };

struct Step {
  Call call;
  int type;  // CV_8UC1, CV_8UC3 or CV_8UC4
};

std::string describe(const std::vector<Step>& steps) {
  std::string text;
  for (const Step& s : steps) {
    if (!text.empty()) text += ", ";
    text += s.call == Call::kInit          ? "init"
            : s.call == Call::kInitFromBox ? "init_from_box"
                                           : "track";
    text += s.type == CV_8UC1 ? "(grey)" : s.type == CV_8UC3 ? "(bgr)" : "(bgra)";
  }
  return text;
}

void run(const std::vector<Step>& steps) {
  const std::string order = describe(steps);
  SCOPED_TRACE(order);
  Tracker tracker;
  FrameLedger ledger;
  std::string done;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const int shift = 2 * static_cast<int>(k);
    // Each frame gets its own buffer (a copy of the one before would share nothing anyway).
    const cv::Mat& frame = ledger.give(render(pentagon(shift), steps[k].type));
    switch (steps[k].call) {
      case Call::kInit:
        tracker.init(frame, pentagon(shift));
        break;
      case Call::kInitFromBox:
        tracker.init_from_box(frame, cv::Rect(75 + shift, 60 + shift / 2, 150, 140));
        break;
      case Call::kTrack:
        tracker.track(frame);
        break;
    }
    done += (done.empty() ? "" : ", ") + describe({steps[k]});
    ledger.expect_untouched(done);
  }
}

TEST(FrameOwnership, EveryOrderOfInitAndTrackWithGreyAndColourFrames) {
  const std::vector<Call> inits = {Call::kInit, Call::kInitFromBox};
  const std::vector<Call> calls = {Call::kInit, Call::kInitFromBox, Call::kTrack};
  const std::vector<int> types = {CV_8UC1, CV_8UC3};
  for (Call first : inits)
    for (int first_type : types)
      for (Call second : calls)
        for (int second_type : types)
          for (Call third : calls)
            for (int third_type : types)
              run({{first, first_type}, {second, second_type}, {third, third_type}});
}

TEST(FrameOwnership, BgraFramesBetweenGreyOnes) {
  run({{Call::kInit, CV_8UC1},
       {Call::kTrack, CV_8UC4},
       {Call::kTrack, CV_8UC1},
       {Call::kInit, CV_8UC4},
       {Call::kInitFromBox, CV_8UC1},
       {Call::kTrack, CV_8UC4}});
}

// While lost the tracker searches the whole frame, through buffers of its own: grey frames
// while lost, then colour ones, and the object found again.
TEST(FrameOwnership, LostOnGreyFramesThenColourOnes) {
  for (const int lost_type : {CV_8UC1, CV_8UC3}) {
    const int found_type = lost_type == CV_8UC1 ? CV_8UC3 : CV_8UC1;
    SCOPED_TRACE(lost_type == CV_8UC1 ? "lost on grey" : "lost on bgr");
    Tracker tracker;
    FrameLedger ledger;
    tracker.init(ledger.give(render(pentagon(0), found_type)), pentagon(0));
    const cv::Mat blank(240, 320, lost_type, cv::Scalar::all(40));
    bool lost = false;
    for (int k = 0; k < 100 && !lost; ++k)
      lost = tracker.track(ledger.give(blank.clone())).state == TrackState::kLost;
    ASSERT_TRUE(lost);
    tracker.track(ledger.give(blank.clone()));
    for (int k = 0; k < 4; ++k) tracker.track(ledger.give(render(pentagon(0), found_type)));
    tracker.track(ledger.give(render(pentagon(0), lost_type)));
    ledger.expect_untouched("losing the object and finding it again");
  }
}

// to_gray's result is the caller's to keep and write: never a view of the frame, and never
// written through a buffer some other Mat shares.
TEST(FrameOwnership, ToGrayGivesABufferOfItsOwn) {
  const cv::Mat grey(10, 12, CV_8UC1, cv::Scalar(7));
  cv::Mat gray;
  to_gray(grey, &gray);
  EXPECT_NE(gray.data, grey.data);
  EXPECT_EQ(grey.u->refcount, 1);
  EXPECT_EQ(cv::norm(gray, grey, cv::NORM_INF), 0.0);
  cv::Mat shared = gray;  // someone else's header on the result
  to_gray(cv::Mat(10, 12, CV_8UC3, cv::Scalar(100, 100, 100)), &gray);
  EXPECT_EQ(gray.at<uchar>(3, 4), 100);
  EXPECT_EQ(shared.at<uchar>(3, 4), 7);
  // A buffer only `gray` holds is reused.
  const uchar* own = gray.data;
  to_gray(cv::Mat(10, 12, CV_8UC4, cv::Scalar(50, 50, 50, 255)), &gray);
  EXPECT_EQ(gray.data, own);
  EXPECT_EQ(gray.at<uchar>(0, 0), 50);
  // Memory the caller owns (a numpy array's, say) is never written either.
  std::vector<uchar> outside(120, 9);
  gray = cv::Mat(10, 12, CV_8UC1, outside.data());
  to_gray(cv::Mat(10, 12, CV_8UC3, cv::Scalar(100, 100, 100)), &gray);
  EXPECT_EQ(outside[0], 9);
  EXPECT_EQ(gray.at<uchar>(0, 0), 100);
}

}  // namespace
}  // namespace scbt
