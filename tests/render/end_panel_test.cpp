// End panels sit beside the car's screen box, never over it when there is room.

#include "render/end_panel.hpp"

#include <gtest/gtest.h>

#include <random>

#include "../sim/scene_builders.hpp"
#include "recording_canvas.hpp"
#include "render/draw_world.hpp"
#include "render/hud.hpp"
#include "render/shapes.hpp"

namespace cardemo {
namespace {

using test::RecordingCanvas;

bool overlaps(const Eigen::Vector2f& a_min, const Eigen::Vector2f& a_max,
              const Eigen::Vector2f& b_min, const Eigen::Vector2f& b_max) {
  return a_min.x() < b_max.x() && b_min.x() < a_max.x() && a_min.y() < b_max.y() &&
         b_min.y() < a_max.y();
}

TEST(PlaceBeside, RightOfTheCarWhenItFits) {
  const Eigen::Vector2f at = placeBeside({1280, 720}, {600, 340}, {680, 380}, {300, 200}, 20);
  EXPECT_EQ(at, Eigen::Vector2f(700, 260));
}

TEST(PlaceBeside, LeftWhenTheRightIsTooNarrow) {
  const Eigen::Vector2f at = placeBeside({1280, 720}, {1000, 340}, {1100, 380}, {300, 200}, 20);
  EXPECT_EQ(at, Eigen::Vector2f(680, 260));
}

TEST(PlaceBeside, BelowThenAboveWhenNeitherSideFits) {
  EXPECT_EQ(placeBeside({640, 720}, {200, 100}, {440, 140}, {300, 200}, 20),
            Eigen::Vector2f(170, 160));
  EXPECT_EQ(placeBeside({640, 720}, {200, 600}, {440, 640}, {300, 200}, 20),
            Eigen::Vector2f(170, 380));
}

TEST(PlaceBeside, ClampedIntoTheViewport) {
  const Eigen::Vector2f at = placeBeside({1280, 720}, {600, 0}, {680, 30}, {300, 200}, 20);
  EXPECT_EQ(at, Eigen::Vector2f(700, 0));
}

TEST(PlaceBeside, NeverOverTheCarOnRandomLayouts) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> pos(0.0f, 1.0f);
  const Eigen::Vector2f panel{320, 220};
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector2f lo{pos(rng) * 1180.0f, pos(rng) * 620.0f};
    const Eigen::Vector2f hi =
        lo + Eigen::Vector2f{20.0f + 80.0f * pos(rng), 20.0f + 80.0f * pos(rng)};
    const Eigen::Vector2f at = placeBeside({1280, 720}, lo, hi, panel, 20);
    EXPECT_FALSE(overlaps(at, at + panel, lo, hi)) << i;
    EXPECT_GE(at.x(), 0.0f);
    EXPECT_GE(at.y(), 0.0f);
    EXPECT_LE(at.x() + panel.x(), 1280.0f);
    EXPECT_LE(at.y() + panel.y(), 720.0f);
  }
}

TEST(EndPanel, DrawsTitleRowsAndHintOutsideTheCar) {
  RecordingCanvas canvas;
  Camera camera;
  const Obb2 car = Obb2::fromDegrees({0, 0}, 30, 4.5, 1.8);
  drawEndPanel(canvas, camera, car,
               {"PARKED", {}, {10, 40, 20, 215}, {{"Time", "6.9 s"}, {"Stars", "3"}}, "R restart"});
  for (const char* text : {"PARKED", "Time", "6.9 s", "Stars", "R restart"}) {
    EXPECT_TRUE(canvas.hasText(text)) << text;
  }
  const auto fills = canvas.fillsOf({10, 40, 20, 215});
  ASSERT_EQ(fills.size(), 1u);
  Eigen::Vector2f lo{1e9f, 1e9f}, hi{-1e9f, -1e9f};
  for (const Eigen::Vector2f& p : projectObb(camera, car)) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  Eigen::Vector2f plo{1e9f, 1e9f}, phi{-1e9f, -1e9f};
  for (const Eigen::Vector2f& p : fills[0].points) {
    plo = plo.cwiseMin(p);
    phi = phi.cwiseMax(p);
  }
  EXPECT_FALSE(overlaps(plo, phi, lo, hi));
}

TEST(EndPanel, GameOverBesideTheCarWithALevelSummary) {
  // Health 1 and a crash at 10 m/s into the car ahead.
  Scene scene = test::sceneWith({test::parkedCar("A", 8.0, 0, 90)});
  scene.player.health = 1;
  scene.player.speed = 10.0;
  World world(std::move(scene));
  for (int i = 0; i < 240 && !world.gameOver(); ++i) world.step(InputFrame{});
  ASSERT_TRUE(world.gameOver());
  RecordingCanvas canvas;
  DrawOptions options;
  options.game_over_rows = {{"Stars", "none"}, {"Best", "4.4 s"}};
  drawFrame(canvas, world, followCamera(world.carBox(), 12.0, {1280, 720}), world.carBox(),
            options);
  EXPECT_TRUE(canvas.hasText("GAME OVER"));
  EXPECT_TRUE(canvas.hasText("Best"));
  EXPECT_TRUE(canvas.hasText("4.4 s"));
}

}  // namespace
}  // namespace cardemo
