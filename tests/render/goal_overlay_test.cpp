// The parking challenge on screen: bay outline, off-screen arrow, timer, PARKED and TIME UP.

#include "render/goal_overlay.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <utility>

#include "../sim/scene_builders.hpp"
#include "recording_canvas.hpp"
#include "render/draw_world.hpp"
#include "render/hud.hpp"
#include "render/shapes.hpp"

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
  drawGoalBay(canvas, camera, view);
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

// A level whose bay is `bay` (world metres), with a task.
Scene taskScene(const Eigen::Vector2d& bay) {
  Scene scene = bayScene(0.0);
  scene.goal->bay.center = bay;
  scene.level = LevelInfo{2, "Reverse bay", "Reverse into the bay between the cars, facing out"};
  return scene;
}

// The panel behind the task's text, as (min, max) corners.
std::pair<Eigen::Vector2f, Eigen::Vector2f> taskPanel(const RecordingCanvas& canvas) {
  const RecordingCanvas::Text* task = canvas.lastText("facing out");
  EXPECT_NE(task, nullptr);
  if (task == nullptr) return {};
  const RecordingCanvas::Fill* panel = backdropOf(canvas, *task);
  EXPECT_NE(panel, nullptr);
  return panel != nullptr ? bounds(*panel) : std::pair<Eigen::Vector2f, Eigen::Vector2f>{};
}

bool disjoint(const std::pair<Eigen::Vector2f, Eigen::Vector2f>& a,
              const std::pair<Eigen::Vector2f, Eigen::Vector2f>& b) {
  return a.first.x() >= b.second.x() || b.first.x() >= a.second.x() ||
         a.first.y() >= b.second.y() || b.first.y() >= a.second.y();
}

// Screen rectangle of a world box under `camera`.
std::pair<Eigen::Vector2f, Eigen::Vector2f> onScreen(const Camera& camera, const Obb2& box) {
  Eigen::Vector2f lo{1e9f, 1e9f}, hi{-1e9f, -1e9f};
  for (const Eigen::Vector2f& p : projectObb(camera, box)) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  return {lo, hi};
}

// The level's task is shown at the start of an attempt, on a backdrop that covers neither the
// car, nor the bay, nor the timer: under the timer, or at the bottom when the bay is up there.
TEST(GoalOverlay, TaskPanelAtTheStartIsClearOfTheCarTheBayAndTheTimer) {
  for (const Eigen::Vector2d& bay : {Eigen::Vector2d(10.0, 0.0), Eigen::Vector2d(0.0, 22.0)}) {
    const Scene scene = taskScene(bay);
    const World world(scene);
    ParkingChallenge c(*scene.goal, 120.0, 100);
    c.observe(world);
    const RecordingCanvas canvas = overlay(world, c);
    ASSERT_TRUE(canvas.hasText("Level 2: Reverse bay"));
    const auto panel = taskPanel(canvas);
    const RecordingCanvas::Fill* timer = backdropOf(canvas, *canvas.lastText("0.0 s"));
    ASSERT_NE(timer, nullptr);
    EXPECT_TRUE(disjoint(panel, bounds(*timer))) << bay.transpose();
    const Camera camera = followCamera(world.carBox(), 12.0, {1280, 720});
    EXPECT_TRUE(disjoint(panel, onScreen(camera, world.carBox()))) << bay.transpose();
    const Obb2 bay_box = Obb2::fromDegrees(bay, 0.0, scene.goal->bay.length, scene.goal->bay.width);
    EXPECT_TRUE(disjoint(panel, onScreen(camera, bay_box))) << bay.transpose();
    EXPECT_TRUE(panel.second.y() < 720.0f && panel.first.x() > 0.0f && panel.second.x() < 1280.0f);
    // Readable: an almost opaque backdrop, the text opaque.
    EXPECT_GE(backdropOf(canvas, *canvas.lastText("facing out"))->color.a, 200);
    EXPECT_EQ(canvas.lastText("facing out")->color.a, 255);
  }
}

// In the whole frame the task also stays clear of the HUD panel at the top left, however many
// rows it has (a replay's playback adds two).
TEST(GoalOverlay, TaskPanelIsClearOfTheHudPanel) {
  Scene scene = taskScene({10.0, 0.0});
  // Long enough to reach under the HUD panel if it were drawn right under the timer.
  scene.level->task =
      "Drive past, then reverse into the bay between the cars so that you end facing out";
  const World world(scene);
  ParkingChallenge c(*scene.goal, 120.0, 100);
  c.observe(world);
  GoalView view;
  view.challenge = &c;
  for (const double playback : {0.0, 2.0}) {
    DrawOptions options;
    options.goal = &view;
    options.playback_speed = playback;
    RecordingCanvas canvas;
    drawFrame(canvas, world, followCamera(world.carBox(), 12.0, {1280, 720}), world.carBox(),
              options);
    // The HUD panel: the first panel-coloured fill, behind the speed.
    const std::vector<RecordingCanvas::Fill> panels = canvas.fillsOf({12, 14, 18, 190});
    ASSERT_FALSE(panels.empty());
    const auto hud = bounds(panels.front());
    const Eigen::Vector2f speed = canvas.lastText("Speed")->at;
    ASSERT_TRUE(speed.x() > hud.first.x() && speed.y() > hud.first.y() &&
                speed.x() < hud.second.x() && speed.y() < hud.second.y());
    EXPECT_TRUE(disjoint(taskPanel(canvas), hud)) << playback;
  }
}

TEST(GoalOverlay, TaskPanelFadesAfterFourSecondsOfPlayAndNeedsATask) {
  const Scene scene = taskScene({10.0, 0.0});
  World world(scene);
  ParkingChallenge c(*scene.goal, 120.0, 100);
  c.observe(world);
  const auto playTo = [&](std::int64_t frame) {
    while (world.frame() < frame) {
      world.step(InputFrame{});
      c.observe(world);
    }
  };
  playTo(450);
  const RecordingCanvas fading = overlay(world, c);  // 3.75 s: half faded
  ASSERT_TRUE(fading.hasText("facing out"));
  EXPECT_LT(fading.lastText("facing out")->color.a, 200);
  EXPECT_GT(fading.lastText("facing out")->color.a, 50);
  playTo(480);
  EXPECT_FALSE(overlay(world, c).hasText("facing out"));
  EXPECT_FALSE(overlay(world, c).hasText("Reverse bay"));

  Scene untitled = taskScene({10.0, 0.0});
  untitled.level->task.clear();
  const World start(untitled);
  ParkingChallenge d(*untitled.goal, 120.0, 100);
  d.observe(start);
  EXPECT_FALSE(overlay(start, d).hasText("Reverse bay"));
}

// A task too long for a narrow window is drawn smaller, still on one line inside it.
TEST(GoalOverlay, TaskPanelFitsANarrowWindow) {
  Scene scene = taskScene({10.0, 0.0});
  scene.level->task = std::string(100, 'w') + " facing out";
  const World world(scene);
  ParkingChallenge c(*scene.goal, 120.0, 100);
  c.observe(world);
  RecordingCanvas canvas({640, 480});
  GoalView view;
  view.challenge = &c;
  drawGoalOverlay(canvas, world, followCamera(world.carBox(), 12.0, {640, 480}), world.carBox(),
                  view);
  const auto panel = taskPanel(canvas);
  EXPECT_GE(panel.first.x(), 0.0f);
  EXPECT_LE(panel.second.x(), 640.0f);
}

// The bay's outline is paint on the ground: the player's car, driving over it, covers it.
TEST(GoalOverlay, BayOutlineIsDrawnUnderThePlayersCar) {
  Scene scene = bayScene(2.0);
  scene.goal->bay.center.y() = 0.5;  // overlapping the car, too far off to be ready: yellow
  const World world(scene);
  ParkingChallenge c(*scene.goal, 120.0, 100);
  c.observe(world);
  GoalView view;
  view.challenge = &c;
  DrawOptions options;
  options.goal = &view;
  RecordingCanvas canvas;
  drawFrame(canvas, world, followCamera(world.carBox(), 30.0, {1280, 720}), world.carBox(),
            options);
  const auto body = canvas.fillsOf(Palette{}.player);
  ASSERT_EQ(body.size(), 1u);
  int outline = 0;
  for (const RecordingCanvas::Line& l : canvas.lines) {
    if (!(l.color == Rgba{255, 214, 70, 255})) continue;
    ++outline;
    EXPECT_LT(l.order, body.front().order) << "the bay's outline is drawn over the car";
  }
  EXPECT_EQ(outline, 4);
  // The timer stays on top of the world.
  const RecordingCanvas::Text* timer = canvas.lastText("par 12.0 s");
  ASSERT_NE(timer, nullptr);
  EXPECT_GT(timer->order, body.front().order);
}

// The camera keeps the level out of the HUD's top strip (hudInsets); the timer must fit in it.
TEST(GoalOverlay, TimerFitsInTheHudsTopStrip) {
  const Scene scene = bayScene(10.0);
  const World world(scene);
  ParkingChallenge c(*scene.goal, 120.0, 100);
  c.observe(world);
  GoalView view;
  view.challenge = &c;
  for (const Eigen::Vector2i& vp :
       {Eigen::Vector2i(1280, 720), Eigen::Vector2i(640, 480), Eigen::Vector2i(1920, 1080)}) {
    RecordingCanvas canvas(vp);
    drawGoalOverlay(canvas, world, followCamera(world.carBox(), 12.0, vp), world.carBox(), view);
    const RecordingCanvas::Text* detail = canvas.lastText("par 12.0 s");
    ASSERT_NE(detail, nullptr);
    const RecordingCanvas::Fill* panel = backdropOf(canvas, *detail);
    ASSERT_NE(panel, nullptr);
    for (const Eigen::Vector2f& p : panel->points) {
      EXPECT_LE(p.y(), hudInsets(vp).top) << vp.transpose();
    }
  }
}

}  // namespace
}  // namespace cardemo
