// PlayFlow: help and pause hold the simulation, the "your turn" hand-over, Enter/Space, speed.

#include "play/play_flow.hpp"

#include <gtest/gtest.h>

namespace cardemo {
namespace {

TEST(PlayFlow, RunsTheClockStepsWhenNothingHolds) {
  PlayFlow flow;
  flow.update(false, false);
  EXPECT_FALSE(flow.holding());
  EXPECT_EQ(flow.stepsToRun(3), 3);
}

TEST(PlayFlow, HelpHoldsTheSimulation) {
  PlayFlow flow;
  flow.toggleHelp();
  EXPECT_TRUE(flow.help());
  EXPECT_TRUE(flow.holding());
  EXPECT_EQ(flow.stepsToRun(5), 0);
  flow.stepOnce();  // N does not step behind the help
  EXPECT_EQ(flow.stepsToRun(5), 0);
  flow.toggleHelp();
  EXPECT_FALSE(flow.holding());
  EXPECT_EQ(flow.stepsToRun(5), 5);
}

TEST(PlayFlow, HelpOverPauseHoldsUntilBothAreOff) {
  PlayFlow flow;
  flow.togglePause();
  flow.toggleHelp();
  flow.toggleHelp();
  EXPECT_TRUE(flow.holding());
  EXPECT_EQ(flow.stepsToRun(2), 0);
  flow.togglePause();
  EXPECT_EQ(flow.stepsToRun(2), 2);
}

TEST(PlayFlow, StepOnceRunsExactlyOneStepWhilePaused) {
  PlayFlow flow;
  flow.stepOnce();  // not paused: nothing special
  EXPECT_EQ(flow.stepsToRun(0), 0);
  flow.togglePause();
  flow.stepOnce();
  EXPECT_EQ(flow.stepsToRun(0), 1);
  EXPECT_EQ(flow.stepsToRun(0), 0);
}

TEST(PlayFlow, ReplayRunningOutStopsAtYourTurnAtOneX) {
  PlayFlow flow;
  flow.update(true, false);
  flow.faster();
  flow.faster();
  EXPECT_EQ(flow.speed(), 4.0);
  EXPECT_EQ(flow.stepsToRun(8), 8);
  flow.update(false, false);  // the replay ran out
  EXPECT_TRUE(flow.yourTurn());
  EXPECT_EQ(flow.speed(), 1.0);
  EXPECT_EQ(flow.chosenSpeed(), 1.0);
  EXPECT_EQ(flow.stepsToRun(8), 0);
  flow.update(false, false);  // still waiting, frame after frame
  EXPECT_EQ(flow.stepsToRun(8), 0);
  flow.driveKeyPressed();
  EXPECT_FALSE(flow.yourTurn());
  EXPECT_EQ(flow.stepsToRun(8), 8);
}

TEST(PlayFlow, NoHandOverWithoutAReplayOrWhenTheReplayEndedTheGame) {
  PlayFlow live;
  live.update(false, false);
  EXPECT_FALSE(live.yourTurn());
  PlayFlow ended;
  ended.update(true, false);
  ended.update(false, true);
  EXPECT_FALSE(ended.yourTurn());
}

TEST(PlayFlow, EnterEndsTheWaitAndRestartsOnlyAnEndedGame) {
  PlayFlow flow;
  flow.update(true, false);
  flow.update(false, false);
  ASSERT_TRUE(flow.yourTurn());
  EXPECT_FALSE(flow.confirm(false));
  EXPECT_FALSE(flow.yourTurn());
  EXPECT_TRUE(flow.confirm(true));
}

TEST(PlayFlow, RestartReplaysAndHandsOverAgain) {
  PlayFlow flow;
  flow.update(true, false);
  flow.update(false, false);
  flow.restarted();
  EXPECT_FALSE(flow.yourTurn());
  flow.update(true, false);
  EXPECT_FALSE(flow.yourTurn());
  flow.update(false, false);
  EXPECT_TRUE(flow.yourTurn());
}

TEST(PlayFlow, SpeedIsClampedAndOnlyAppliesToPlayback) {
  PlayFlow flow;
  for (int i = 0; i < 10; ++i) flow.faster();
  EXPECT_EQ(flow.chosenSpeed(), PlayFlow::kMaxSpeed);
  EXPECT_EQ(flow.speed(), 1.0);  // live play runs in real time
  for (int i = 0; i < 10; ++i) flow.slower();
  EXPECT_EQ(flow.chosenSpeed(), PlayFlow::kMinSpeed);
  flow.update(true, false);
  EXPECT_EQ(flow.speed(), PlayFlow::kMinSpeed);
}

// N means "one step" until the level is parked, then "next level" (only when there is one).
TEST(PlayFlow, NStepsWhilePausedAndOpensTheNextLevelOnceParked) {
  PlayFlow flow;
  const LevelLinks links{true, true};
  flow.togglePause();
  EXPECT_EQ(flow.next(false, links), LevelExit::kStay);
  EXPECT_EQ(flow.stepsToRun(0), 1);  // still the single step
  EXPECT_EQ(flow.next(true, links), LevelExit::kNextLevel);
  EXPECT_EQ(flow.stepsToRun(0), 0);                                       // and no step with it
  EXPECT_EQ(flow.next(true, LevelLinks{true, false}), LevelExit::kStay);  // the last level
  EXPECT_EQ(flow.next(true, LevelLinks{}), LevelExit::kStay);  // a scene given on the command line
  flow.togglePause();
  EXPECT_EQ(flow.next(false, links), LevelExit::kStay);  // not paused: N does nothing
  EXPECT_EQ(flow.stepsToRun(0), 0);
}

TEST(PlayFlow, EscapeReturnsToThePickerOnlyWhenStartedFromIt) {
  EXPECT_EQ(escapeExit(LevelLinks{true, true}), LevelExit::kPicker);
  EXPECT_EQ(escapeExit(LevelLinks{true, false}), LevelExit::kPicker);
  EXPECT_EQ(escapeExit(LevelLinks{}), LevelExit::kQuit);
}

TEST(PlayFlow, EndPanelListsOnlyTheKeysThatWork) {
  EXPECT_EQ(endPanelKeys(LevelLinks{true, true}, true),
            "Enter retry    N next level    Esc levels");
  EXPECT_EQ(endPanelKeys(LevelLinks{true, true}, false), "Enter retry    Esc levels");  // TIME UP
  EXPECT_EQ(endPanelKeys(LevelLinks{true, false}, true), "Enter retry    Esc levels");
  EXPECT_EQ(endPanelKeys(LevelLinks{}, true), "Enter retry    Esc quit");
}

}  // namespace
}  // namespace cardemo
