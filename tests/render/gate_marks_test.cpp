#include "render/gate_marks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "recording_canvas.hpp"
#include "sim/world.hpp"

namespace cardemo::gate_marks_test {
namespace {

Gate across(std::string name, double x) {
  Gate g;
  g.name = std::move(name);
  g.from = {x, -2.0};
  g.to = {x, 2.0};
  g.center = {x, 0.0};
  return g;
}

// A car at rest at the origin, facing +x, with three gates ahead at x = 2, 4 and 6.
Scene gatedScene() {
  Scene s;
  s.player.max_speed = 5.0;
  Goal goal;
  goal.bay.center = {20.0, 0.0};
  goal.gates = {across("one", 2.0), across("two", 4.0), across("three", 6.0)};
  s.goal = goal;
  return s;
}

bool hasText(const test::RecordingCanvas& canvas, const std::string& text, const Rgba& color) {
  return std::any_of(canvas.texts.begin(), canvas.texts.end(), [&](const auto& t) {
    return t.text == text && t.color.r == color.r && t.color.g == color.g && t.color.b == color.b;
  });
}

bool hasText(const test::RecordingCanvas& canvas, const std::string& text) {
  return std::any_of(canvas.texts.begin(), canvas.texts.end(),
                     [&](const auto& t) { return t.text == text; });
}

constexpr Rgba kGreen{90, 230, 120, 255};
constexpr Rgba kYellow{255, 214, 70, 255};

TEST(GateMarks, NextIsHighlightedPassedAreTicked) {
  const Scene scene = gatedScene();
  World world(scene);
  ParkingChallenge challenge(*scene.goal, world.settings().hz, scene.player.health);
  challenge.observe(world);
  const Camera camera{{3.0, 0.0}, 40.0, {1280, 720}};
  test::RecordingCanvas before;
  drawGates(before, camera, challenge);
  EXPECT_TRUE(hasText(before, "1", kYellow));
  EXPECT_TRUE(hasText(before, "2"));
  EXPECT_FALSE(hasText(before, "2", kYellow));
  // Drive through the first gate only.
  InputFrame up;
  up.up = true;
  while (world.car().position.x() < 2.5) {
    world.step(up);
    challenge.observe(world);
  }
  ASSERT_EQ(challenge.gates().passed(), 1u);
  test::RecordingCanvas after;
  drawGates(after, camera, challenge);
  EXPECT_TRUE(hasText(after, "1\xE2\x9C\x93", kGreen));
  EXPECT_TRUE(hasText(after, "2", kYellow));
  EXPECT_FALSE(freshGateWarning(challenge).has_value());
}

TEST(GateMarks, AMissIsSaidForThreeSeconds) {
  Scene scene = gatedScene();
  scene.goal->gates[0].from = {2.0, 1.0};  // gate one no longer spans the car's path
  scene.goal->gates[0].to = {2.0, 3.0};
  scene.goal->gates[2] = across("three", 60.0);  // out of reach of the coasting car
  World world(scene);
  ParkingChallenge challenge(*scene.goal, world.settings().hz, scene.player.health);
  challenge.observe(world);
  InputFrame up;
  up.up = true;
  while (world.car().position.x() < 4.5) {
    world.step(up);
    challenge.observe(world);
  }
  ASSERT_EQ(challenge.gates().misses(), 1);
  EXPECT_EQ(freshGateWarning(challenge), "missed gate 1: one");
  const std::int64_t missed = challenge.gates().lastMiss()->frame;
  while (world.frame() < missed + 359) {
    world.step({});
    challenge.observe(world);
  }
  EXPECT_TRUE(freshGateWarning(challenge).has_value());
  world.step({});
  challenge.observe(world);
  EXPECT_FALSE(freshGateWarning(challenge).has_value());  // 360 frames: 3 s at 120 Hz
}

}  // namespace
}  // namespace cardemo::gate_marks_test
