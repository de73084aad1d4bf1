// The parking challenge on screen: bay outline, off-screen arrow, timer, PARKED and TIME UP.

#include "render/goal_overlay.hpp"

#include <gtest/gtest.h>

#include <utility>

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

// Bounding box of a fill, as (min, max) corners.
std::pair<Eigen::Vector2f, Eigen::Vector2f> bounds(const RecordingCanvas::Fill& f) {
  Eigen::Vector2f lo = f.points[0], hi = f.points[0];
  for (const Eigen::Vector2f& p : f.points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  return {lo, hi};
}

// The fill drawn just before `text` (its panel or backdrop).
const RecordingCanvas::Fill* backdropOf(const RecordingCanvas& canvas,
                                        const RecordingCanvas::Text& text) {
  const RecordingCanvas::Fill* found = nullptr;
  for (const RecordingCanvas::Fill& f : canvas.fills) {
    if (f.order < text.order && (found == nullptr || f.order > found->order)) found = &f;
  }
  return found;
}

// PAUSED in a level: drawn last, on its own opaque backdrop, clear of the timer panel at the top
// centre (it used to be drawn under it); with the help shown, in the help panel's title.
TEST(GoalOverlay, PausedIsDrawnLastAndClearOfTheTimer) {
  const Scene scene = bayScene(10.0);
  const World world(scene);
  ParkingChallenge c(*scene.goal, 120.0, 100);
  c.observe(world);
  GoalView view;
  view.challenge = &c;
  DrawOptions options;
  options.paused = true;
  options.goal = &view;
  const Camera camera = followCamera(world.carBox(), 12.0, {1280, 720});
  RecordingCanvas canvas;
  drawFrame(canvas, world, camera, world.carBox(), options);
  const RecordingCanvas::Text* paused = canvas.lastText("PAUSED");
  const RecordingCanvas::Text* timer = canvas.lastText("0.0 s");
  ASSERT_NE(paused, nullptr);
  ASSERT_NE(timer, nullptr);
  EXPECT_EQ(paused->order, canvas.texts.back().order) << "something was drawn over PAUSED";
  for (const RecordingCanvas::Fill& f : canvas.fills) EXPECT_LT(f.order, paused->order);
  const RecordingCanvas::Fill* backdrop = backdropOf(canvas, *paused);
  const RecordingCanvas::Fill* timer_panel = backdropOf(canvas, *timer);
  ASSERT_NE(backdrop, nullptr);
  ASSERT_NE(timer_panel, nullptr);
  EXPECT_GE(backdrop->color.a, 200);
  const auto [lo, hi] = bounds(*backdrop);
  EXPECT_TRUE(paused->at.x() >= lo.x() && paused->at.y() >= lo.y() && paused->at.x() <= hi.x() &&
              paused->at.y() <= hi.y());
  const auto [tlo, thi] = bounds(*timer_panel);
  EXPECT_TRUE(lo.y() > thi.y() || hi.y() < tlo.y() || lo.x() > thi.x() || hi.x() < tlo.x())
      << "PAUSED's backdrop overlaps the timer panel";

  options.help = true;
  RecordingCanvas help;
  drawFrame(help, world, camera, world.carBox(), options);
  std::size_t count = 0;
  for (const RecordingCanvas::Text& t : help.texts) count += t.text == "PAUSED" ? 1 : 0;
  EXPECT_EQ(count, 1u);
  ASSERT_NE(help.lastText("Keys"), nullptr);
  ASSERT_NE(help.lastText("PAUSED"), nullptr);
  EXPECT_GT(help.lastText("PAUSED")->order, help.lastText("Keys")->order);
  EXPECT_FLOAT_EQ(help.lastText("PAUSED")->at.y(), help.lastText("Keys")->at.y());
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
