// The parking challenge on screen: bay outline, off-screen arrow, timer, PARKED and TIME UP.

#include "render/goal_overlay.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <utility>

#include "../sim/scene_builders.hpp"
#include "recording_canvas.hpp"
#include "render/draw_world.hpp"
#include "render/ground_layer.hpp"
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

// A car rolling slowly (0.2 m/s, slower than the goal's max_speed) in the bay's centre: it moves
// at the first step, so the level clock runs from frame 0, and it parks once the hold is over.
Scene rollingInBay() {
  Scene s = bayScene(0.0);
  s.player.speed = 0.2;
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
  const Scene scene = rollingInBay();
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
  for (const char* text : {"PARKED", "Time", "\xE2\x98\x85 parked", "\xE2\x98\x85 no damage",
                           "\xE2\x98\x85 within par 12.0 s", "Best", "5.0 s"}) {
    EXPECT_TRUE(canvas.hasText(text)) << text;
  }
  view.new_best = true;
  EXPECT_TRUE(overlay(world, c, view).hasText("new best"));
}

// Steps `world` holding `keys` until the challenge `c` is over (at most a minute).
void runUntilOver(World& world, ParkingChallenge& c, const InputFrame& keys = {}) {
  for (int i = 0; i < 7200 && !c.over(); ++i) {
    world.step(keys);
    c.observe(world);
  }
  ASSERT_TRUE(c.over());
}

const InputFrame kThrottle{true, false, false, false};

// A bay 50 m away and half a second to reach it: a car that drives off runs out of time.
Scene timeUpScene() {
  Scene scene = bayScene(50.0);
  scene.goal->time_limit = 0.5;
  return scene;
}

// TIME UP says what ended the run and what was still off.
TEST(GoalOverlay, TimeUpPanelSaysWhatEndedTheRun) {
  const Scene scene = timeUpScene();
  World world(scene);
  ParkingChallenge c(*scene.goal, 120.0, 100);
  c.observe(world);
  runUntilOver(world, c, kThrottle);
  ASSERT_TRUE(c.timedOut());
  const RecordingCanvas canvas = overlay(world, c);
  EXPECT_TRUE(canvas.hasText("TIME UP"));
  EXPECT_EQ(canvas.rowValue("Ended"), "time limit 0.5 s");
  EXPECT_NE(canvas.rowValue("Still off").find(" m to the bay"), std::string::npos);
  EXPECT_EQ(canvas.rowValue("Damage"), "0");
  EXPECT_TRUE(canvas.hasText("none yet"));
  EXPECT_FALSE(canvas.hasText("\xE2\x98\x85")) << "no stars for a run that did not park";
}

// A missed star says why: over par by how much.
TEST(GoalOverlay, ParkedPanelNamesAMissedStar) {
  Scene scene = rollingInBay();
  scene.goal->par_time = 0.1;
  World world(scene);
  ParkingChallenge c(*scene.goal, 120.0, 100);
  c.observe(world);
  runUntilOver(world, c);
  ASSERT_TRUE(c.parkedFrame().has_value());
  const RecordingCanvas canvas = overlay(world, c);
  EXPECT_TRUE(canvas.hasText("\xE2\x98\x85 parked"));
  EXPECT_TRUE(canvas.hasText("\xE2\x98\x85 no damage"));
  EXPECT_TRUE(canvas.hasText("\xE2\x98\x86 over par by 0.4 s"));
}

// A level's GAME OVER says the car was wrecked and what was still off.
TEST(GoalOverlay, GameOverInALevelSaysWhatEndedTheRun) {
  Scene scene = test::sceneWith({test::parkedCar("A", 8.0, 0, 90)});
  scene.player.health = 1;
  scene.player.speed = 10.0;
  Goal goal;
  goal.bay.center = {0.0, 6.0};
  scene.goal = goal;
  World world(scene);
  ParkingChallenge c(*scene.goal, 120.0, 1);
  c.observe(world);
  runUntilOver(world, c);
  ASSERT_TRUE(world.gameOver());
  ASSERT_TRUE(c.wrecked());
  GoalView view;
  view.challenge = &c;
  DrawOptions options;
  options.goal = &view;
  options.game_over_rows = runSummaryRows(world, view);
  RecordingCanvas canvas;
  drawFrame(canvas, world, followCamera(world.carBox(), 12.0, {1280, 720}), world.carBox(),
            options);
  EXPECT_TRUE(canvas.hasText("GAME OVER"));
  EXPECT_EQ(canvas.rowValue("Ended"), "wrecked (health 0)");
  EXPECT_FALSE(canvas.rowValue("Still off").empty());
  EXPECT_EQ(canvas.rowValue("Damage"), "1");
}

// The line under the timer: distance while driving, the hold while stopped in the bay, then what
// ended the run; the end panel lists the keys it is given.
TEST(GoalOverlay, TimerDetailFollowsTheRunAndThePanelListsTheKeys) {
  const Scene scene = rollingInBay();
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

// A chain of two bays: the timer line says which bay is next, the outline moves to the second
// bay once the first is parked, and the ground shows both, numbered.
TEST(GoalOverlay, AChainShowsWhichBayIsNext) {
  Scene scene = bayScene(0.0);
  ParkingBay second = scene.goal->bay;
  second.center = {12.0, 0.0};
  scene.goal->next_bays = {second};
  World world(scene);
  ParkingChallenge c(*scene.goal, 120.0, 100);
  c.observe(world);
  EXPECT_EQ(timerDetail(c), "par 12.0 s   bay 1/2   left 60.0 s   hold 0.0 / 0.5 s");
  while (c.baysParked() == 0) {
    world.step(InputFrame{});
    c.observe(world);
  }
  EXPECT_EQ(timerDetail(c), "par 12.0 s   bay 2/2   left 60.0 s   bay 12.0 m");
  // The bay outlined is the second: its centre is where the outline's corners average.
  RecordingCanvas outlined;
  GoalView view;
  view.challenge = &c;
  const Camera camera = followCamera(world.carBox(), 12.0, {1280, 720});
  drawGoalBay(outlined, camera, view);
  ASSERT_FALSE(outlined.lines.empty());
  Eigen::Vector2f sum = Eigen::Vector2f::Zero();
  for (const RecordingCanvas::Line& l : outlined.lines) sum += l.a + l.b;
  const Eigen::Vector2f centre = sum / (2.0f * static_cast<float>(outlined.lines.size()));
  EXPECT_LT((centre - camera.toScreen(second.center)).norm(), 1.0f);
  // Both bays are painted on the ground, numbered 1 and 2 (no "P").
  RecordingCanvas ground;
  drawMarkings(ground, camera, scene, Palette{});
  EXPECT_TRUE(ground.hasText("1"));
  EXPECT_TRUE(ground.hasText("2"));
  EXPECT_FALSE(ground.hasText("P"));
}

// Until the car moves the clock does not run: a player reading the task loses no time.
TEST(GoalOverlay, TheTimerWaitsForTheFirstMove) {
  const Scene scene = bayScene(10.0);
  World world(scene);
  ParkingChallenge c(*scene.goal, 120.0, 100);
  c.observe(world);
  for (int i = 0; i < 240; ++i) {
    world.step(InputFrame{false, false, i % 2 == 0, i % 2 == 1});  // steering only
    c.observe(world);
  }
  EXPECT_TRUE(overlay(world, c).hasText("0.0 s"));
  EXPECT_EQ(timerDetail(c), "par 12.0 s   left 60.0 s   bay 10.0 m");
  for (int i = 0; i < 120; ++i) {
    world.step(kThrottle);
    c.observe(world);
  }
  EXPECT_TRUE(overlay(world, c).hasText("1.0 s"));
  EXPECT_NE(timerDetail(c).find("left 59.0 s"), std::string::npos) << timerDetail(c);
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
  runUntilOver(world, c, kThrottle);
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

// The task shows for the first 4 s of play, and after them until the car first moves; then it
// fades out over half a second.
TEST(GoalOverlay, TaskPanelStaysUntilTheCarMovesThenFades) {
  for (const int wait : {0, 600}) {
    const Scene scene = taskScene({10.0, 0.0});
    World world(scene);
    ParkingChallenge c(*scene.goal, 120.0, 100);
    c.observe(world);
    const auto playTo = [&](std::int64_t frame, const InputFrame& keys) {
      while (world.frame() < frame) {
        world.step(keys);
        c.observe(world);
      }
    };
    playTo(wait, InputFrame{});
    EXPECT_TRUE(overlay(world, c).hasText("facing out")) << "waiting " << wait;
    // Driving from here: with no wait, fading at 3.75 s and gone at 4 s; after a wait, fading a
    // quarter of a second after the car moved and gone after half a second.
    const std::int64_t fade_at = wait == 0 ? 450 : wait + 30;
    const std::int64_t gone_at = wait == 0 ? 480 : wait + 61;
    playTo(fade_at, kThrottle);
    const RecordingCanvas fading = overlay(world, c);
    ASSERT_TRUE(fading.hasText("facing out")) << wait;
    EXPECT_LT(fading.lastText("facing out")->color.a, 200) << wait;
    EXPECT_GT(fading.lastText("facing out")->color.a, 50) << wait;
    playTo(gone_at, kThrottle);
    EXPECT_FALSE(overlay(world, c).hasText("facing out")) << wait;
    EXPECT_FALSE(overlay(world, c).hasText("Reverse bay")) << wait;
  }

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
  // The heading arrow is paint too.
  const std::vector<RecordingCanvas::Fill> arrow = canvas.fillsOf({255, 214, 70, 255});
  ASSERT_EQ(arrow.size(), 2u);  // shaft and head
  for (const RecordingCanvas::Fill& f : arrow) EXPECT_LT(f.order, body.front().order);
  // The timer stays on top of the world.
  const RecordingCanvas::Text* timer = canvas.lastText("par 12.0 s");
  ASSERT_NE(timer, nullptr);
  EXPECT_GT(timer->order, body.front().order);
}

// The camera keeps the level out of the HUD's top strip (hudInsets); the timer must fit in it,
// with the readout's row as well.
TEST(GoalOverlay, TimerFitsInTheHudsTopStrip) {
  const Scene scene = bayScene(10.0);
  const World world(scene);
  ParkingChallenge c(*scene.goal, 120.0, 100);
  c.observe(world);
  GoalView view;
  view.challenge = &c;
  const Scene near = bayScene(0.9);
  const World near_world(near);
  ParkingChallenge near_challenge(*near.goal, 120.0, 100);
  near_challenge.observe(near_world);
  GoalView near_view;
  near_view.challenge = &near_challenge;
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
    // Its tallest form, with the readout's row, too.
    RecordingCanvas with_row(vp);
    drawGoalOverlay(with_row, near_world, followCamera(near_world.carBox(), 12.0, vp),
                    near_world.carBox(), near_view);
    ASSERT_NE(with_row.lastText("0.9 m forward"), nullptr);
    const RecordingCanvas::Fill* tall = backdropOf(with_row, *with_row.lastText("par 12.0 s"));
    ASSERT_NE(tall, nullptr);
    EXPECT_GT(bounds(*tall).second.y(), bounds(*panel).second.y());
    EXPECT_LE(bounds(*tall).second.y(), timerPanelBottom(vp) + 1e-3f) << vp.transpose();
    EXPECT_LE(timerPanelBottom(vp), hudInsets(vp).top) << vp.transpose();
  }
}

// Near the bay the timer panel says what is still off, under its detail line, in the readout's
// words and order; far away it does not (the detail line gives the distance).
TEST(GoalOverlay, ReadoutUnderTheTimerNearTheBay) {
  const Scene scene = bayScene(0.9);  // the bay's centre 0.9 m ahead of the car's
  const World world(scene);
  ParkingChallenge c(*scene.goal, 120.0, 100);
  c.observe(world);
  const RecordingCanvas canvas = overlay(world, c);
  const RecordingCanvas::Text* readout = canvas.lastText("0.9 m forward");
  const RecordingCanvas::Text* detail = canvas.lastText("par 12.0 s");
  ASSERT_NE(readout, nullptr);
  ASSERT_NE(detail, nullptr);
  EXPECT_EQ(readout->color, (Rgba{255, 214, 70, 255}));
  EXPECT_GT(readout->at.y(), detail->at.y());
  const auto [lo, hi] = bounds(*backdropOf(canvas, *detail));
  EXPECT_TRUE(readout->at.x() > lo.x() && readout->at.y() > lo.y() && readout->at.x() < hi.x() &&
              readout->at.y() < hi.y())
      << "the readout is outside the timer panel";

  // Several at once on one line, in the order a driver fixes them.
  Scene skewed = bayScene(0.0);
  skewed.goal->bay.center = {1.0, 0.6};
  skewed.goal->bay.heading_deg = 20.0;
  const World skew_world(skewed);
  ParkingChallenge d(*skewed.goal, 120.0, 100);
  d.observe(skew_world);
  EXPECT_TRUE(overlay(skew_world, d).hasText("1.0 m forward   0.6 m left   turn 20\xC2\xB0 left"));

  // In position but rolling: stop.
  Scene rolling = bayScene(0.0);
  rolling.player.speed = 1.0;
  const World roll_world(rolling);
  ParkingChallenge e(*rolling.goal, 120.0, 100);
  e.observe(roll_world);
  EXPECT_NE(overlay(roll_world, e).lastText("stop"), nullptr);

  // Far away: no readout.
  const Scene far = bayScene(20.0);
  const World far_world(far);
  ParkingChallenge f(*far.goal, 120.0, 100);
  f.observe(far_world);
  const RecordingCanvas far_canvas = overlay(far_world, f);
  EXPECT_TRUE(far_canvas.hasText("bay 20.0 m"));
  EXPECT_FALSE(far_canvas.hasText("forward"));
  EXPECT_FALSE(far_canvas.hasText("to the bay"));
}

// While the checks hold, a bar under the timer fills over the hold time.
TEST(GoalOverlay, HoldBarFillsOverTheHoldTime) {
  const Scene scene = rollingInBay();
  World world(scene);
  ParkingChallenge c(*scene.goal, 120.0, 100);
  c.observe(world);
  const Rgba trough{55, 58, 64, 255};
  const Rgba filled{90, 230, 120, 255};
  // The fill drawn right after the trough (the bay's arrow is green too, but drawn earlier).
  const auto barFraction = [&](const RecordingCanvas& canvas) {
    const std::vector<RecordingCanvas::Fill> troughs = canvas.fillsOf(trough);
    EXPECT_EQ(troughs.size(), 1u);
    if (troughs.size() != 1u) return -1.0f;
    for (const RecordingCanvas::Fill& f : canvas.fillsOf(filled)) {
      if (f.order == troughs[0].order + 1) return f.width() / troughs[0].width();
    }
    return 0.0f;
  };
  EXPECT_FLOAT_EQ(barFraction(overlay(world, c)), 0.0f);
  for (int i = 0; i < 30; ++i) {
    world.step(InputFrame{});
    c.observe(world);
  }
  EXPECT_NEAR(barFraction(overlay(world, c)), 0.5f, 1e-4f);
  for (int i = 0; i < 15; ++i) {
    world.step(InputFrame{});
    c.observe(world);
  }
  EXPECT_NEAR(barFraction(overlay(world, c)), 0.75f, 1e-4f);
  runUntilOver(world, c);
  EXPECT_TRUE(overlay(world, c).fillsOf(trough).empty()) << "parked: no bar";
}

// The bay shows the heading it wants: an arrow along it, or one each way with either_direction.
TEST(GoalOverlay, BayArrowPointsTheWayToFace) {
  for (const bool either : {false, true}) {
    Scene scene = bayScene(0.0);
    scene.goal->bay.center = {0.0, 8.0};
    scene.goal->bay.heading_deg = 90.0;  // facing up the screen
    scene.goal->either_direction = either;
    const World world(scene);
    ParkingChallenge c(*scene.goal, 120.0, 100);
    c.observe(world);
    const Camera camera = followCamera(world.carBox(), 12.0, {1280, 720});
    RecordingCanvas canvas;
    GoalView view;
    view.challenge = &c;
    drawGoalBay(canvas, camera, view);
    const Eigen::Vector2f centre = camera.toScreen(scene.goal->bay.center);
    std::vector<float> tips;  // screen y of each arrowhead's tip relative to the bay's centre
    for (const RecordingCanvas::Fill& f : canvas.fillsOf({255, 214, 70, 255})) {
      if (f.points.size() != 3) continue;
      float tip = 0.0f;
      for (const Eigen::Vector2f& p : f.points) {
        if (std::abs(p.y() - centre.y()) > std::abs(tip)) tip = p.y() - centre.y();
      }
      EXPECT_NEAR(f.centroid().x(), centre.x(), 1e-3f);
      tips.push_back(tip);
    }
    ASSERT_EQ(tips.size(), either ? 2u : 1u);
    EXPECT_LT(tips[0], 0.0f) << "the arrow points down the screen, not up";
    if (either) {
      EXPECT_GT(tips[1], 0.0f);
    }
  }
}

}  // namespace
}  // namespace cardemo
