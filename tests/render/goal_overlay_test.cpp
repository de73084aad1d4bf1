// The parking challenge on screen: bay outline, off-screen arrow, timer, PARKED and TIME UP.

#include "render/goal_overlay.hpp"

#include <gtest/gtest.h>

#include "../sim/scene_builders.hpp"
#include "recording_canvas.hpp"
#include "render/draw_world.hpp"

namespace cardemo {
namespace {

using test::RecordingCanvas;

Scene bayScene(double bay_x) {
  Scene s = test::sceneWith({});
  Goal g;
  g.bay.center = {bay_x, 0.0};
  g.par_time = 12.0;
  g.time_limit = 60.0;
  s.goal = g;
  return s;
}

RecordingCanvas overlay(const World& world, const ParkingChallenge& c, GoalView view = {}) {
  RecordingCanvas canvas;
  view.challenge = &c;
  const Camera camera = followCamera(world.carBox(), 12.0, {1280, 720});
  drawGoalOverlay(canvas, world, camera, world.carBox(), view);
  return canvas;
}

TEST(GoalOverlay, StarsAndSecondsText) {
  EXPECT_EQ(starsText(0), "\xE2\x98\x86\xE2\x98\x86\xE2\x98\x86");
  EXPECT_EQ(starsText(2), "\xE2\x98\x85\xE2\x98\x85\xE2\x98\x86");
  EXPECT_EQ(secondsText(6.8666), "6.9 s");
}

TEST(GoalOverlay, EdgeAnchorOnlyForPointsOffScreen) {
  EXPECT_FALSE(edgeAnchor({1280, 720}, {700, 400}, 40).has_value());
  const std::optional<Eigen::Vector2f> right = edgeAnchor({1280, 720}, {5000, 360}, 40);
  ASSERT_TRUE(right.has_value());
  EXPECT_FLOAT_EQ(right->x(), 1240.0f);
  EXPECT_FLOAT_EQ(right->y(), 360.0f);
  const std::optional<Eigen::Vector2f> corner = edgeAnchor({1280, 720}, {-10000, -10000}, 40);
  ASSERT_TRUE(corner.has_value());
  EXPECT_FLOAT_EQ(corner->y(), 40.0f);  // the vertical edge is reached first
  EXPECT_GT(corner->x(), 40.0f);
}

TEST(GoalOverlay, BayOnScreenHasOutlineAndTimerButNoArrow) {
  const Scene scene = bayScene(10.0);
  const World world(scene);
  ParkingChallenge c(*scene.goal, 120.0, 100);
  c.observe(world);
  const RecordingCanvas canvas = overlay(world, c);
  EXPECT_EQ(canvas.linesOf({255, 214, 70, 255}), 4u);  // the bay's four sides only
  EXPECT_TRUE(canvas.hasText("0.0 s"));
  EXPECT_TRUE(canvas.hasText("par 12.0 s"));
  EXPECT_TRUE(canvas.hasText("left 60.0 s"));
  EXPECT_FALSE(canvas.hasText("PARKED"));
}

TEST(GoalOverlay, BayOffScreenGetsAnArrowWithTheDistance) {
  const Scene scene = bayScene(400.0);
  const World world(scene);
  ParkingChallenge c(*scene.goal, 120.0, 100);
  c.observe(world);
  const RecordingCanvas canvas = overlay(world, c);
  EXPECT_GT(canvas.linesOf({255, 214, 70, 255}), 4u);
  EXPECT_TRUE(canvas.hasText("400 m"));
}

TEST(GoalOverlay, ParkedPanelWithSummaryAndBest) {
  const Scene scene = bayScene(0.0);
  World world(scene);
  ParkingChallenge c(*scene.goal, 120.0, 100);
  c.observe(world);
  while (!c.over()) {  // at rest in the bay: parked once the hold is over
    world.step(InputFrame{});
    c.observe(world);
  }
  ASSERT_TRUE(c.parkedFrame().has_value());
  GoalView view;
  view.best = ParkingScore{600, 5.0, 0, 3};
  const RecordingCanvas canvas = overlay(world, c, view);
  for (const char* text : {"PARKED", "Time", "Damage", "Stars", "Best", "5.0 s"}) {
    EXPECT_TRUE(canvas.hasText(text)) << text;
  }
  view.new_best = true;
  EXPECT_TRUE(overlay(world, c, view).hasText("new best"));
}

// Steps `world` with no input until the challenge `c` is over.
void runUntilOver(World& world, ParkingChallenge& c) {
  while (!c.over()) {
    world.step(InputFrame{});
    c.observe(world);
  }
}

// A bay 50 m away and a quarter of a second to reach it: the run ends TIME UP.
Scene timeUpScene() {
  Scene scene = bayScene(50.0);
  scene.goal->time_limit = 0.25;
  return scene;
}

TEST(GoalOverlay, TimeUpPanel) {
  const Scene scene = timeUpScene();
  World world(scene);
  ParkingChallenge c(*scene.goal, 120.0, 100);
  c.observe(world);
  runUntilOver(world, c);
  ASSERT_TRUE(c.timedOut());
  const RecordingCanvas canvas = overlay(world, c);
  EXPECT_TRUE(canvas.hasText("TIME UP"));
  EXPECT_TRUE(canvas.hasText("none yet"));
}

// The line under the timer: distance while driving, the hold while stopped in the bay, then what
// ended the run; the end panel lists the keys it is given.
TEST(GoalOverlay, TimerDetailFollowsTheRunAndThePanelListsTheKeys) {
  const Scene scene = bayScene(0.0);
  World world(scene);
  ParkingChallenge c(*scene.goal, 120.0, 100);
  c.observe(world);
  EXPECT_EQ(timerDetail(c), "par 12.0 s   left 60.0 s   hold 0.0 / 0.5 s");
  for (int i = 0; i < 30; ++i) {
    world.step(InputFrame{});
    c.observe(world);
  }
  EXPECT_EQ(timerDetail(c), "par 12.0 s   left 59.8 s   hold 0.2 / 0.5 s");
  runUntilOver(world, c);
  EXPECT_EQ(timerDetail(c), "parked   par 12.0 s");
  GoalView view;
  view.keys = "Enter retry    N next level    Esc levels";
  const RecordingCanvas canvas = overlay(world, c, view);
  EXPECT_TRUE(canvas.hasText("Enter retry    N next level    Esc levels"));
  EXPECT_FALSE(canvas.hasText("Enter restart    Esc quit"));
  EXPECT_TRUE(canvas.hasText("0.5 s"));  // the timer stopped at the parked time

  const Scene far = bayScene(10.0);
  const World away(far);
  ParkingChallenge d(*far.goal, 120.0, 100);
  d.observe(away);
  EXPECT_EQ(timerDetail(d), "par 12.0 s   left 60.0 s   bay 10.0 m");
}

TEST(GoalOverlay, TimerDetailSaysTimeUp) {
  const Scene scene = timeUpScene();
  World world(scene);
  ParkingChallenge c(*scene.goal, 120.0, 100);
  c.observe(world);
  runUntilOver(world, c);
  EXPECT_EQ(timerDetail(c), "time up");
}

}  // namespace
}  // namespace cardemo
