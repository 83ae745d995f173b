#include <gtest/gtest.h>

#include <random>

#include "scbt/app/interactive_run.h"

namespace scbt {
namespace {

void click_square(InteractiveSession* s) {
  for (const Point& p : {Point(10, 10), Point(60, 10), Point(60, 50), Point(10, 50)}) {
    EXPECT_EQ(s->on_left_click(p), SessionAction::kNone);
  }
}

TEST(InteractiveSession, StartsDrawingWithoutPolygonAndPausedWithOne) {
  EXPECT_EQ(InteractiveSession(false).mode(), InteractiveMode::kDrawing);
  EXPECT_EQ(InteractiveSession(true).mode(), InteractiveMode::kPaused);
  EXPECT_FALSE(InteractiveSession(false).wants_frame());
  EXPECT_FALSE(InteractiveSession(true).wants_frame());
}

TEST(InteractiveSession, ClicksThenEnterOrMiddleClickCloseThePolygon) {
  for (int closer : {kKeyEnter, kKeyLineFeed, -1}) {
    InteractiveSession s(false);
    click_square(&s);
    EXPECT_EQ(s.draft().size(), 4u);
    const SessionAction a = closer < 0 ? s.on_middle_click() : s.on_key(closer);
    ASSERT_EQ(a, SessionAction::kInitialise);
    const Polygon polygon = s.take_polygon();
    ASSERT_EQ(polygon.size(), 4u);
    EXPECT_EQ(polygon[2], Point(60, 50));
    s.polygon_accepted();
    EXPECT_EQ(s.mode(), InteractiveMode::kPaused);
    EXPECT_TRUE(s.draft().empty());
  }
}

TEST(InteractiveSession, UnusablePolygonsDoNotClose) {
  InteractiveSession s(false);
  s.on_left_click({10, 10});
  s.on_left_click({20, 20});
  EXPECT_EQ(s.on_key(kKeyEnter), SessionAction::kNone);
  EXPECT_NE(s.message().find("cannot close"), std::string::npos);
  s.on_left_click({30, 30});  // collinear: no area
  EXPECT_EQ(s.on_middle_click(), SessionAction::kNone);
  EXPECT_EQ(s.mode(), InteractiveMode::kDrawing);
  // A bow tie crosses itself.
  InteractiveSession bow(false);
  for (const Point& p : {Point(0, 0), Point(40, 40), Point(40, 0), Point(0, 40)}) {
    bow.on_left_click(p);
  }
  EXPECT_EQ(bow.on_key(kKeyEnter), SessionAction::kNone);
  bow.on_key(kKeyBackspace);
  EXPECT_EQ(bow.draft().size(), 3u);
  EXPECT_EQ(bow.on_key(kKeyEnter), SessionAction::kInitialise);
}

TEST(InteractiveSession, SpaceRunsAndPausesStepTracksOneFrame) {
  InteractiveSession s(true);
  s.on_key(kKeySpace);
  EXPECT_EQ(s.mode(), InteractiveMode::kRunning);
  EXPECT_TRUE(s.wants_frame());
  s.frame_done();
  EXPECT_TRUE(s.wants_frame());  // running continues
  s.on_key(kKeySpace);
  EXPECT_EQ(s.mode(), InteractiveMode::kPaused);
  EXPECT_FALSE(s.wants_frame());
  s.on_key('s');
  EXPECT_TRUE(s.wants_frame());
  s.frame_done();
  EXPECT_FALSE(s.wants_frame());
  EXPECT_EQ(s.mode(), InteractiveMode::kPaused);
}

TEST(InteractiveSession, ClicksOutsideDrawingAreIgnoredAndRRedraws) {
  InteractiveSession s(true);
  EXPECT_EQ(s.on_left_click({5, 5}), SessionAction::kNone);
  EXPECT_TRUE(s.draft().empty());
  s.on_key(kKeySpace);
  s.on_key('r');
  EXPECT_EQ(s.mode(), InteractiveMode::kDrawing);
  EXPECT_FALSE(s.wants_frame());
  s.on_key(kKeySpace);  // space does nothing while drawing
  EXPECT_EQ(s.mode(), InteractiveMode::kDrawing);
  click_square(&s);
  ASSERT_EQ(s.on_middle_click(), SessionAction::kInitialise);
  s.take_polygon();
  s.polygon_rejected("outside the frame");
  EXPECT_EQ(s.mode(), InteractiveMode::kDrawing);
  EXPECT_NE(s.message().find("outside the frame"), std::string::npos);
}

TEST(InteractiveSession, EscapeOrQQuitsFromEveryMode) {
  for (int key : {kKeyEscape, static_cast<int>('q')}) {
    InteractiveSession drawing(false);
    EXPECT_EQ(drawing.on_key(key), SessionAction::kQuit);
    InteractiveSession running(true);
    running.on_key(kKeySpace);
    EXPECT_EQ(running.on_key(key), SessionAction::kQuit);
    EXPECT_EQ(running.mode(), InteractiveMode::kQuit);
    EXPECT_FALSE(running.wants_frame());
  }
}

TEST(InteractiveSession, EndOfInputStopsRunningAndSteps) {
  InteractiveSession s(true);
  s.on_key(kKeySpace);
  s.end_of_input();
  EXPECT_EQ(s.mode(), InteractiveMode::kPaused);
  EXPECT_TRUE(s.input_ended());
  s.on_key(kKeySpace);
  s.on_key('s');
  EXPECT_FALSE(s.wants_frame());
  EXPECT_EQ(s.on_key(kKeyEscape), SessionAction::kQuit);
}

// Property: under any key/click sequence the session stays consistent: it only asks for frames
// when running or stepping once, never while drawing, and a quit is final.
TEST(InteractiveSession, RandomEventSequencesKeepInvariants) {
  std::mt19937 rng(7);
  const int keys[] = {kKeySpace, 's', 'r', kKeyEnter, kKeyBackspace, 'x', -1};
  for (int trial = 0; trial < 200; ++trial) {
    InteractiveSession s(trial % 2 == 0);
    for (int step = 0; step < 60 && s.mode() != InteractiveMode::kQuit; ++step) {
      const int choice = static_cast<int>(rng() % 10);
      SessionAction a = SessionAction::kNone;
      if (choice < 3) {
        a = s.on_left_click({static_cast<double>(rng() % 100), static_cast<double>(rng() % 100)});
      } else if (choice == 3) {
        a = s.on_middle_click();
      } else if (choice == 4 && rng() % 10 == 0) {
        a = s.on_key(kKeyEscape);
      } else {
        a = s.on_key(keys[rng() % 7]);
      }
      if (a == SessionAction::kInitialise) {
        EXPECT_GE(s.take_polygon().size(), 3u);
        s.polygon_accepted();
      }
      if (s.mode() == InteractiveMode::kDrawing) {
        EXPECT_FALSE(s.wants_frame());
      }
      if (s.mode() == InteractiveMode::kPaused || s.mode() == InteractiveMode::kRunning) {
        EXPECT_TRUE(s.draft().empty());
      }
      if (s.wants_frame()) s.frame_done();
      if (rng() % 50 == 0) s.end_of_input();
      if (s.input_ended()) {
        EXPECT_FALSE(s.wants_frame());
      }
    }
    if (s.mode() == InteractiveMode::kQuit) {
      EXPECT_EQ(s.on_key(kKeySpace), SessionAction::kQuit);
      EXPECT_FALSE(s.wants_frame());
    }
  }
}

}  // namespace
}  // namespace scbt
