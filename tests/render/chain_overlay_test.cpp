// Free drive's bay chain on screen: the highlighted bay painted and outlined as a level's goal,
// the next one faint, the timer with the time left, the count and the best, the task, and the
// panel when the chain is over.

#include <gtest/gtest.h>

#include "../sim/scene_builders.hpp"
#include "recording_canvas.hpp"
#include "render/draw_world.hpp"
#include "render/goal_overlay.hpp"

namespace cardemo {
namespace {

using test::parkedCar;
using test::RecordingCanvas;
using test::sceneWith;

constexpr Rgba kTarget{255, 214, 70, 255};
constexpr Rgba kNextBay{255, 214, 70, 90};

// A row of cars facing north at x = 0, 5 and 15 (free bays at x = -5, 10 and 20); the car in the
// aisle 8 m north of the bay at x = 10, which is the first of the chain.
Scene rowLot(double player_y = 8.0) {
  Scene s =
      sceneWith({parkedCar("a", 0, 0, 90), parkedCar("b", 5, 0, 90), parkedCar("c", 15, 0, 90)},
                10.0, player_y, 90.0);
  s.name = "row-lot";
  return s;
}

GoalView chainView(const BayChain& chain) {
  GoalView view;
  view.challenge = &chain.challenge();
  view.chain = &chain;
  return view;
}

RecordingCanvas drawnFrame(const World& world, const GoalView& view,
                           std::vector<std::pair<std::string, std::string>> game_over_rows = {}) {
  RecordingCanvas canvas;
  DrawOptions options;
  options.goal = &view;
  options.game_over_rows = std::move(game_over_rows);
  drawFrame(canvas, world, followCamera(world.carBox(), 12.0, {1280, 720}), world.carBox(),
            options);
  return canvas;
}

TEST(ChainOverlay, TheHighlightedBayIsTheGoalsAndTheNextIsFaint) {
  const Scene scene = rowLot();
  const World world(scene);
  BayChain chain(scene, 120.0);
  chain.observe(world);
  ASSERT_EQ(chain.current(), 0u);
  GoalView view = chainView(chain);
  view.chain_best = ChainScore{5, 12000, 100.0};
  const RecordingCanvas canvas = drawnFrame(world, view);
  EXPECT_EQ(canvas.linesOf(kTarget), 4u) << "the highlighted bay's outline";
  EXPECT_EQ(canvas.linesOf(kNextBay), 4u) << "the next bay's, faint";
  // Painted as a level's goal bay: the tinted box and its P, at the highlighted bay.
  const Palette palette;
  Rgba tint = palette.goal_bay;
  tint.a = 45;
  const std::vector<RecordingCanvas::Fill> paint = canvas.fillsOf(tint);
  ASSERT_EQ(paint.size(), 1u);
  const Camera camera = followCamera(world.carBox(), 12.0, {1280, 720});
  EXPECT_LT((paint[0].centroid() - camera.toScreen(chain.bays()[0].bay.center)).norm(), 0.5f);
  EXPECT_TRUE(canvas.hasText("P"));
  EXPECT_TRUE(canvas.hasText("180.0 s left"));
  EXPECT_TRUE(canvas.hasText("0 parked   best 5   bay 8.0 m"));
  // The task, as a level's, until the car first moves.
  EXPECT_TRUE(canvas.hasText("Free drive"));
  EXPECT_TRUE(canvas.hasText(chainTaskText()));
  EXPECT_FALSE(canvas.hasText("TIME UP"));

  // A plain lot (no chain) draws none of it.
  DrawOptions plain;
  RecordingCanvas none;
  drawFrame(none, world, camera, world.carBox(), plain);
  EXPECT_EQ(none.linesOf(kTarget), 0u);
  EXPECT_TRUE(none.fillsOf(tint).empty());
}

TEST(ChainOverlay, TheHoldAndTheTaskFollowTheChainsClock) {
  // Standing in the first bay: its hold runs, and the task stays (the car has not moved).
  const Scene scene = rowLot(0.0);
  World world(scene);
  BayChain chain(scene, 120.0);
  chain.observe(world);
  for (int i = 0; i < 700; ++i) {
    world.step({});
    chain.observe(world);
    if (i == 0) {
      EXPECT_EQ(chainDetail(chainView(chain)), "0 parked   hold 0.0 / 0.5 s");
    }
  }
  ASSERT_EQ(chain.count(), 1);
  EXPECT_TRUE(drawnFrame(world, chainView(chain)).hasText(chainTaskText())) << "not moved yet";
  // Once the car has moved, a bay's fresh check (whose own clock waits for a move, as after a
  // bay parked at a standstill) does not bring the task back: the chain's clock has started.
  InputFrame up;
  up.up = true;
  for (int i = 0; i < 60; ++i) {
    world.step(up);
    chain.observe(world);
  }
  for (int i = 0; i < 240; ++i) {
    world.step({});
    chain.observe(world);
  }
  ParkingChallenge fresh(chain.challenge().goal(), 120.0, 100);
  fresh.observe(world);
  ASSERT_FALSE(fresh.clockStart().has_value());
  GoalView view = chainView(chain);
  view.challenge = &fresh;
  const RecordingCanvas canvas = drawnFrame(world, view);
  EXPECT_TRUE(canvas.hasText("1 parked"));
  EXPECT_FALSE(canvas.hasText(chainTaskText()));
}

TEST(ChainOverlay, TimeUpShowsTheCountAndWhetherItIsANewBest) {
  const Scene scene = rowLot();
  World world(scene);
  BayChainSettings settings;
  settings.time_limit = 0.5;
  BayChain chain(scene, 120.0, settings);
  chain.observe(world);
  InputFrame up;
  up.up = true;
  for (int i = 0; i < 200 && !chain.over(); ++i) {
    world.step(up);
    chain.observe(world);
  }
  ASSERT_TRUE(chain.timedOut());
  GoalView view = chainView(chain);
  RecordingCanvas canvas = drawnFrame(world, view);
  EXPECT_TRUE(canvas.hasText("TIME UP"));
  EXPECT_EQ(canvas.rowValue("Bays parked"), "0");
  EXPECT_EQ(canvas.rowValue("Ended"), "time limit 0.5 s");
  EXPECT_EQ(canvas.rowValue("Best"), "none yet");
  EXPECT_TRUE(canvas.hasText("0.0 s left"));
  EXPECT_TRUE(canvas.hasText("time up   0 parked"));
  EXPECT_FALSE(canvas.hasText(chainTaskText()));
  EXPECT_EQ(canvas.linesOf(kNextBay), 0u) << "nothing comes next";
  view.new_best = true;
  EXPECT_EQ(drawnFrame(world, view).rowValue("Best"), "new best!");
  view.new_best = false;
  view.chain_best = ChainScore{1, 1476, 12.3};
  EXPECT_EQ(drawnFrame(world, view).rowValue("Best"), "1 bay in 12.3 s");
}

TEST(ChainOverlay, AWreckedChainFillsTheGameOverPanel) {
  Scene scene = rowLot();
  scene.parked.push_back(parkedCar("across", 10, 20, 0));
  scene.player.health = 5;
  World world(scene);
  BayChain chain(scene, 120.0);
  chain.observe(world);
  InputFrame up;
  up.up = true;
  for (int i = 0; i < 600 && !chain.over(); ++i) {
    world.step(up);
    chain.observe(world);
  }
  ASSERT_TRUE(chain.wrecked());
  const GoalView view = chainView(chain);
  const auto rows = chainSummaryRows(world, view);
  const RecordingCanvas canvas = drawnFrame(world, view, rows);
  EXPECT_TRUE(canvas.hasText("GAME OVER"));
  EXPECT_FALSE(canvas.hasText("TIME UP"));
  EXPECT_EQ(canvas.rowValue("Ended"), "wrecked (health 0)");
  EXPECT_EQ(canvas.rowValue("Damage"), "5");
  EXPECT_TRUE(canvas.hasText("wrecked   0 parked"));
}

TEST(ChainOverlay, ScoreTextCountsBays) {
  EXPECT_EQ(chainScoreText({1, 1476, 12.3}), "1 bay in 12.3 s");
  EXPECT_EQ(chainScoreText({4, 20424, 170.2}), "4 bays in 170.2 s");
  BayChainSettings settings;
  settings.time_limit = 90.0;
  EXPECT_EQ(chainTaskText(settings),
            "Park in the highlighted bay, then the next: as many as you can in 90 s");
}

}  // namespace
}  // namespace cardemo
