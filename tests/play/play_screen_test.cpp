// PlayScreen, the rules both platforms run: the clock, pause, help, N, Esc, the YOUR TURN
// hand-over, zoom, interpolation, sound notes and the window requests, with no window.

#include "play/play_screen.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "play_screen_driver.hpp"

namespace cardemo {
namespace {

using test::kStep;
using test::press;
using test::release;
using test::screenConfig;
using test::ScreenDriver;
using K = PlayActionKind;

TEST(PlayScreen, RunsTheStepsTheElapsedTimeIsWorth) {
  ScreenDriver d(screenConfig(test::openFloor()));
  EXPECT_EQ(d.frame({}, 3 * kStep).steps, 3);
  EXPECT_EQ(d.frame({}, 0.5 * kStep).steps, 0);
  EXPECT_EQ(d.frame({}, 0.5 * kStep).steps, 1);  // the halves add up
  EXPECT_EQ(d.worldFrame(), 4);
}

TEST(PlayScreen, TheClockClampsCatchUpSteps) {
  ScreenDriver d(screenConfig(test::openFloor()));
  EXPECT_EQ(d.frame({}, 10.0).steps, PlayScreen::kMaxStepsPerFrame);
  // The rest of the ten seconds is dropped, not caught up on later.
  EXPECT_EQ(d.frame({}, 0.0).steps, 0);
  EXPECT_EQ(d.worldFrame(), PlayScreen::kMaxStepsPerFrame);
}

TEST(PlayScreen, PauseHoldsTheClock) {
  ScreenDriver d(screenConfig(test::openFloor()));
  const PlayFrame& paused = d.act(K::kPause, 1.0);
  EXPECT_EQ(paused.steps, 0);
  EXPECT_TRUE(paused.draw.paused);
  EXPECT_FALSE(paused.draw.help);
  // Nothing accumulated while paused: resuming runs no step for the second that passed.
  const PlayFrame& resumed = d.act(K::kPause, 0.0);
  EXPECT_EQ(resumed.steps, 0);
  EXPECT_FALSE(resumed.draw.paused);
  EXPECT_EQ(d.frame({}, 2 * kStep).steps, 2);
  // Half a step while paused is not added to half a step after it.
  (void)d.act(K::kPause, 0.5 * kStep);
  EXPECT_EQ(d.act(K::kPause, 0.5 * kStep).steps, 0);
  EXPECT_EQ(d.frame({}, 0.5 * kStep).steps, 1);
}

TEST(PlayScreen, HelpHoldsTheClockAndShowsPaused) {
  ScreenDriver d(screenConfig(test::openFloor()));
  const PlayFrame& help = d.act(K::kHelp, 1.0);
  EXPECT_EQ(help.steps, 0);
  EXPECT_TRUE(help.draw.help);
  EXPECT_TRUE(help.draw.paused);
  EXPECT_EQ(d.act(K::kNext, 1.0).steps, 0);  // N does not step behind the help
  EXPECT_EQ(d.act(K::kHelp, 0.0).steps, 0);
  EXPECT_EQ(d.frame({}, kStep).steps, 1);
  EXPECT_EQ(d.worldFrame(), 1);
}

TEST(PlayScreen, NextStepsOnceWhilePaused) {
  ScreenDriver d(screenConfig(test::openFloor()));
  (void)d.act(K::kPause);
  EXPECT_EQ(d.act(K::kNext, 1.0).steps, 1);
  EXPECT_EQ(d.frame({}, 1.0).steps, 0);
  EXPECT_EQ(d.act(K::kNext, 0.0).steps, 1);
  EXPECT_EQ(d.worldFrame(), 2);
  // P then N in one frame: the order of the actions counts, so N steps once.
  ScreenDriver e(screenConfig(test::openFloor()));
  EXPECT_EQ(e.frame({{K::kPause}, {K::kNext}}, 1.0).steps, 1);
}

TEST(PlayScreen, NextOpensTheNextLevelOnlyOnceParked) {
  PlayScreenConfig config = screenConfig(test::rollInLevel());
  config.links = {true, true};
  ScreenDriver d(std::move(config));
  EXPECT_EQ(d.act(K::kNext, kStep).exit, LevelExit::kStay);  // not parked: nothing
  (void)d.frame({press(DriveKey::kDown)});
  d.runToEnd();
  ASSERT_TRUE(d.screen().level().challenge()->parkedFrame().has_value());
  const PlayFrame& next = d.act(K::kNext);
  EXPECT_EQ(next.exit, LevelExit::kNextLevel);
  EXPECT_EQ(d.screen().outcome().exit, LevelExit::kNextLevel);

  // Parked, but no level follows (the last one, or a scene named on the command line).
  PlayScreenConfig last = screenConfig(test::rollInLevel());
  last.links = {true, false};
  ScreenDriver l(std::move(last));
  (void)l.frame({press(DriveKey::kDown)});
  l.runToEnd();
  const std::int64_t frame = l.worldFrame();
  EXPECT_EQ(l.act(K::kNext, 1.0).exit, LevelExit::kStay);
  EXPECT_EQ(l.worldFrame(), frame);
}

TEST(PlayScreen, EscapeGoesBackToThePickerOrQuits) {
  PlayScreenConfig picked = screenConfig(test::openFloor());
  picked.links = {true, false};
  ScreenDriver from_picker(std::move(picked));
  EXPECT_EQ(from_picker.act(K::kEscape, 1.0).exit, LevelExit::kPicker);
  EXPECT_EQ(from_picker.worldFrame(), 0);  // leaving steps nothing

  ScreenDriver named(screenConfig(test::openFloor()));
  EXPECT_EQ(named.act(K::kEscape).exit, LevelExit::kQuit);

  // Closing the window always quits, even from the picker, and wins over Esc.
  PlayScreenConfig closed = screenConfig(test::openFloor());
  closed.links = {true, true};
  ScreenDriver c(std::move(closed));
  EXPECT_EQ(c.frame({{K::kEscape}, {K::kQuit}}).exit, LevelExit::kQuit);

  // Not leaving at all: the outcome says quit (as when a signal stops the game).
  ScreenDriver stays(screenConfig(test::openFloor()));
  EXPECT_EQ(stays.frame({}, kStep).exit, LevelExit::kStay);
  EXPECT_EQ(stays.screen().outcome().exit, LevelExit::kQuit);
}

TEST(PlayScreen, AReplayHandsOverAtYourTurn) {
  PlayScreenConfig config = screenConfig(test::openFloor());
  config.session.playback = {{3, InputFrame{true, false, false, false}}};
  config.replay_path = "demo.replay";
  ScreenDriver d(std::move(config));
  const PlayFrame& playing = d.frame({}, kStep);
  EXPECT_EQ(playing.draw.status, "replaying demo.replay (2 frames left)");
  EXPECT_EQ(playing.draw.playback_speed, 1.0);
  // The replay runs out mid-frame: the frame stops there and waits.
  const PlayFrame& out = d.frame({}, 5 * kStep);
  EXPECT_EQ(out.steps, 2);
  EXPECT_EQ(out.draw.banner, PlayScreen::kYourTurn);
  EXPECT_EQ(d.frame({}, 1.0).steps, 0);
  EXPECT_EQ(d.worldFrame(), 3);
  // The first driving key takes over, at once and at 1x.
  const PlayFrame& live = d.frame({press(DriveKey::kLeft)}, kStep);
  EXPECT_EQ(live.steps, 1);
  EXPECT_EQ(live.draw.banner, "");
  EXPECT_NE(d.screen().session().world().car().steer, 0.0);

  // Enter takes over too (and does not restart: the run has not ended).
  PlayScreenConfig again = screenConfig(test::openFloor());
  again.session.playback = {{2, InputFrame{}}};
  ScreenDriver e(std::move(again));
  EXPECT_EQ(e.frame({}, 4 * kStep).steps, 2);
  EXPECT_EQ(e.act(K::kConfirm, kStep).steps, 1);
  EXPECT_EQ(e.screen().session().sceneAttempt(), 1);
}

TEST(PlayScreen, ReplaySpeedScalesTheClockOnlyWhilePlayingBack) {
  PlayScreenConfig config = screenConfig(test::openFloor());
  config.session.playback = {{100, InputFrame{}}};
  ScreenDriver d(std::move(config));
  EXPECT_EQ(d.act(K::kFaster, 2 * kStep).steps, 4);
  EXPECT_EQ(d.frame({}, 0.0).draw.playback_speed, 2.0);
  EXPECT_EQ(d.frame({{K::kSlower}, {K::kSlower}}, 4 * kStep).steps, 2);
  ScreenDriver live(screenConfig(test::openFloor()));
  EXPECT_EQ(live.act(K::kFaster, 2 * kStep).steps, 2);  // live play is always 1x
}

TEST(PlayScreen, ConfirmRestartsOnlyOnceTheRunHasEnded) {
  ScreenDriver d(screenConfig(test::crashScene()));
  (void)d.act(K::kConfirm, kStep);
  EXPECT_EQ(d.screen().session().sceneAttempt(), 1);
  d.runToEnd();
  ASSERT_TRUE(d.screen().session().ended());
  const PlayFrame& over = d.act(K::kPause, 1.0);
  EXPECT_FALSE(over.draw.paused);  // the end panel, not PAUSED, says what is going on
  EXPECT_TRUE(over.draw.run_over);
  EXPECT_EQ(over.draw.game_over_keys, "Enter retry    Esc quit");
  const PlayFrame& again = d.act(K::kConfirm, 0.0);
  EXPECT_EQ(d.screen().session().sceneAttempt(), 2);
  EXPECT_EQ(d.worldFrame(), 0);
  EXPECT_EQ(again.draw.status, "attempt 2");
  EXPECT_FALSE(again.draw.run_over);
}

TEST(PlayScreen, SpaceIsTheHandbrakeAndRetryOnceEnded) {
  // Space gives a handbrake press and a confirm (play/key_map); the confirm retries only at the
  // end, so a press while driving just brakes.
  ScreenDriver d(screenConfig(test::crashScene()));
  (void)d.frame({press(DriveKey::kHandbrake), {K::kConfirm}}, kStep);
  EXPECT_EQ(d.screen().session().sceneAttempt(), 1);
  EXPECT_EQ(d.worldFrame(), 1);
}

TEST(PlayScreen, RestartStartsAFreshAttemptAtAnyTime) {
  ScreenDriver d(screenConfig(test::openFloor(5.0)));
  (void)d.frame({press(DriveKey::kUp)}, 4 * kStep);
  const PlayFrame& out = d.act(K::kRestart, 2 * kStep);
  EXPECT_EQ(out.steps, 2);
  EXPECT_EQ(d.worldFrame(), 2);
  EXPECT_EQ(d.screen().session().sceneAttempt(), 2);
  // The held key was let go with the old attempt: the new one coasts.
  World coast(test::openFloor(5.0));
  coast.step({});
  coast.step({});
  EXPECT_EQ(d.screen().session().world().stateHash(), coast.stateHash());
}

TEST(PlayScreen, AKeyTappedBetweenStepsCountsForOneStep) {
  ScreenDriver d(screenConfig(test::openFloor()));
  (void)d.frame({press(DriveKey::kUp), release(DriveKey::kUp)}, 0.0);
  (void)d.frame({}, kStep);
  World expected(test::openFloor());
  expected.step({true, false, false, false});
  EXPECT_EQ(d.screen().session().world().stateHash(), expected.stateHash());
  // Focus lost: every key is let go.
  (void)d.frame({press(DriveKey::kUp), {K::kReleaseAll}}, 0.0);
  (void)d.frame({}, kStep);
  expected.step({});
  EXPECT_EQ(d.screen().session().world().stateHash(), expected.stateHash());
}

TEST(PlayScreen, ZoomClampsAtBothEnds) {
  ScreenDriver d(screenConfig(test::openFloor()));
  const double base_ppm = d.frame().camera.pixels_per_metre;
  std::vector<PlayAction> in(30, PlayAction{K::kZoomIn});
  const PlayFrame& closest = d.frame(in);
  EXPECT_DOUBLE_EQ(d.screen().userZoom(), PlayScreen::kMaxZoom / PlayScreen::kDefaultZoom);
  EXPECT_NEAR(closest.camera.pixels_per_metre / base_ppm,
              PlayScreen::kMaxZoom / PlayScreen::kDefaultZoom, 1e-12);
  std::vector<PlayAction> out(60, PlayAction{K::kZoomOut});
  (void)d.frame(out);
  EXPECT_DOUBLE_EQ(d.screen().userZoom(), PlayScreen::kMinZoom / PlayScreen::kDefaultZoom);
  (void)d.act(K::kZoomIn);
  EXPECT_DOUBLE_EQ(d.screen().userZoom(), 1.25 * PlayScreen::kMinZoom / PlayScreen::kDefaultZoom);
}

TEST(PlayScreen, InterpolatesOnlyWhenNotFrozen) {
  const Scene scene = test::openFloor(10.0);
  ScreenDriver d(screenConfig(scene));
  const Obb2 before = World(scene).carBox();
  const PlayFrame& half = d.frame({}, 1.5 * kStep);  // one step and half of the next
  ASSERT_EQ(half.steps, 1);
  const Obb2 after = half.world->carBox();
  ASSERT_GT(after.center.x() - before.center.x(), 0.05);
  const double half_x = 0.5 * (before.center.x() + after.center.x());
  EXPECT_NEAR(half.player_box.center.x(), half_x, 1e-9);
  // A frame with no time passing still blends: the half step is still pending.
  EXPECT_NEAR(d.frame().player_box.center.x(), half_x, 1e-9);
  // Paused: the car is drawn where it is, not between two steps.
  EXPECT_NEAR(d.act(K::kPause).player_box.center.x(), after.center.x(), 1e-12);
}

TEST(PlayScreen, FramesPerSecondSkipTheFirstFrame) {
  ScreenDriver d(screenConfig(test::openFloor()));
  EXPECT_EQ(d.frame({}, 1e-6).draw.fps, 0.0);
  EXPECT_DOUBLE_EQ(d.frame({}, 0.02).draw.fps, 50.0);
  EXPECT_DOUBLE_EQ(d.frame({}, 0.01).draw.fps, 0.95 * 50.0 + 0.05 * 100.0);
}

TEST(PlayScreen, MuteTogglesTheSoundAndTheNote) {
  ScreenDriver d(screenConfig(test::openFloor()));
  const PlayFrame& off = d.act(K::kToggleMute);
  EXPECT_TRUE(off.muted);
  EXPECT_EQ(off.draw.status, "sound off");
  const PlayFrame& on = d.act(K::kToggleMute);
  EXPECT_FALSE(on.muted);
  EXPECT_EQ(on.draw.status, "sound on");
  EXPECT_TRUE(d.screen().takeMessages().empty());
  // Twice in one frame is one toggle: the keys act once per frame.
  EXPECT_TRUE(d.frame({{K::kToggleMute}, {K::kToggleMute}}).muted);
}

TEST(PlayScreen, NoSoundIsSaidOnceAProgram) {
  PlayScreenConfig silent = screenConfig(test::openFloor());
  silent.sound = {false, "no audio device", false};
  ScreenDriver d(silent);
  EXPECT_EQ(d.screen().takeMessages(), std::vector<std::string>{"cardemo play: no audio device"});
  EXPECT_TRUE(d.screen().soundProblemReported());
  const PlayFrame& m = d.act(K::kToggleMute);
  EXPECT_EQ(m.draw.status, "no sound: see the terminal");
  EXPECT_TRUE(d.screen().takeMessages().empty());

  // Started muted: nothing is said until M is pressed.
  silent.muted = true;
  ScreenDriver muted(silent);
  EXPECT_TRUE(muted.screen().takeMessages().empty());
  EXPECT_FALSE(muted.screen().soundProblemReported());
  (void)muted.act(K::kToggleMute);
  EXPECT_EQ(muted.screen().takeMessages(),
            std::vector<std::string>{"cardemo play: no audio device"});

  // Said by an earlier level: not again.
  silent.muted = false;
  silent.sound.problem_reported = true;
  ScreenDriver later(silent);
  (void)later.act(K::kToggleMute);
  EXPECT_TRUE(later.screen().takeMessages().empty());
}

TEST(PlayScreen, WindowRequestsAndTogglesPassThrough) {
  ScreenDriver d(screenConfig(test::openFloor()));
  const PlayFrame& shot = d.frame({{K::kScreenshot}, {K::kFullscreen}, {K::kDebugOverlay}});
  EXPECT_TRUE(shot.screenshot);
  EXPECT_TRUE(shot.toggle_fullscreen);
  EXPECT_TRUE(shot.draw.debug_overlay);
  const PlayFrame& next = d.frame({{K::kFullscreen}, {K::kFullscreen}});
  EXPECT_FALSE(next.screenshot);         // a request lasts one frame
  EXPECT_FALSE(next.toggle_fullscreen);  // on and off again
  EXPECT_TRUE(next.draw.debug_overlay);  // a toggle stays
  d.screen().showNote("saved cardemo-shot-001.png");
  EXPECT_EQ(d.frame().draw.status, "saved cardemo-shot-001.png");
}

TEST(PlayScreen, TheDrawingFollowsTheWorldAndTheWindow) {
  ScreenDriver d(screenConfig(test::openFloor()));
  const PlayFrame& f = d.frame({}, kStep);
  EXPECT_EQ(f.world, &d.screen().session().world());
  EXPECT_EQ(f.camera.viewport, Eigen::Vector2i(1280, 720));
  EXPECT_NE(f.draw.effects, nullptr);
  EXPECT_TRUE(f.draw.sprites);
  EXPECT_EQ(f.draw.goal, nullptr);  // no goal in this scene
  PlayScreen& screen = d.screen();
  const std::vector<PlayAction> none;
  const PlayFrame& wide = screen.frame({none, PadState{}, 0.0, {1920, 1080}});
  EXPECT_EQ(wide.camera.viewport, Eigen::Vector2i(1920, 1080));

  PlayScreenConfig level = screenConfig(test::rollInLevel());
  level.links = {true, true};
  ScreenDriver l(std::move(level));
  const PlayFrame& g = l.frame();
  ASSERT_NE(g.draw.goal, nullptr);
  EXPECT_EQ(g.draw.goal->challenge, l.screen().level().challenge());
  EXPECT_EQ(g.draw.goal->keys, "Enter retry    Esc levels");
}

TEST(PlayScreen, TheControllerDrivesAndTakesOverFromAReplay) {
  PlayScreenConfig config = screenConfig(test::openFloor());
  config.session.playback = {{1, InputFrame{}}};
  PlayScreen screen(std::move(config));
  const std::vector<PlayAction> none;
  EXPECT_EQ(screen.frame({none, PadState{}, 2 * kStep, {1280, 720}}).steps, 1);
  EXPECT_EQ(screen.frame({none, PadState{}, kStep, {1280, 720}}).steps, 0);  // YOUR TURN
  PadState pad;
  pad.throttle = 1.0;
  const PlayFrame& f = screen.frame({none, pad, kStep, {1280, 720}});
  EXPECT_EQ(f.steps, 1);
  EXPECT_GT(screen.session().world().car().speed, 0.0);
}

TEST(PlayScreen, ReportsEachSimulatedFrameAsItIsStepped) {
  PlayScreenConfig config = screenConfig(test::openFloor());
  std::vector<std::int64_t> seen;
  config.on_step = [&seen](std::int64_t frame) { seen.push_back(frame); };
  ScreenDriver d(std::move(config));
  (void)d.frame({}, 3 * kStep);
  (void)d.act(K::kRestart, 2 * kStep);
  EXPECT_EQ(seen, (std::vector<std::int64_t>{1, 2, 3, 1, 2}));
}

}  // namespace
}  // namespace cardemo
