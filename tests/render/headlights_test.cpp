// Headlight beams: on the ground, under the cars and walls, stopped by what they meet.

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "../sim/scene_builders.hpp"
#include "recording_canvas.hpp"
#include "render/draw_world.hpp"

namespace cardemo {
namespace {

using test::parkedCar;
using test::RecordingCanvas;
using test::sceneWith;

// The player at the origin facing +x: its front bumper is at x = 2.25 m.
constexpr double kBumperX = 2.25;

Rgba beamColor() {
  Rgba c = Palette{}.headlight;
  c.a = 20;
  return c;
}

struct Drawn {
  RecordingCanvas canvas;
  Camera camera;
};

Drawn drawFrameOf(const World& world) {
  Drawn d{RecordingCanvas({1280, 720}), followCamera(world.carBox(), 40.0, {1280, 720})};
  drawFrame(d.canvas, world, d.camera, world.carBox(), {});
  return d;
}

// How far ahead (world x) the beams reach, and their smallest x.
std::pair<double, double> beamReach(const Drawn& d) {
  double lo = 1e9;
  double hi = -1e9;
  for (const auto& f : d.canvas.fillsOf(beamColor())) {
    for (const Eigen::Vector2f& p : f.points) {
      lo = std::min(lo, d.camera.toWorld(p).x());
      hi = std::max(hi, d.camera.toWorld(p).x());
    }
  }
  return {lo, hi};
}

TEST(Headlights, BeamsLightTheGroundAheadInTheOpen) {
  const World world(sceneWith({}));
  const Drawn d = drawFrameOf(world);
  ASSERT_FALSE(d.canvas.fillsOf(beamColor()).empty());
  const auto [lo, hi] = beamReach(d);
  EXPECT_NEAR(lo, kBumperX, 1e-3);
  EXPECT_GT(hi, kBumperX + 3.0);  // about 3.2 m of lit ground
}

TEST(Headlights, BeamsAreUnderAParkedCarAndStopAtIt) {
  // Crosswise 1.8 m ahead: its near side is at x = 3.1 and it spans the beams' width.
  const World world(sceneWith({parkedCar("A", 4.0, 0.0, 90.0)}));
  const Drawn d = drawFrameOf(world);
  const auto body = d.canvas.fillsOf(parkedColor("A"));
  ASSERT_FALSE(body.empty());
  const auto beams = d.canvas.fillsOf(beamColor());
  ASSERT_FALSE(beams.empty()) << "the ground before the car is still lit";
  for (const auto& b : beams) EXPECT_LT(b.order, body.front().order) << "a beam over the car";
  EXPECT_LE(beamReach(d).second, 3.1 + 1e-3) << "light through the car";
}

TEST(Headlights, BeamsAreUnderAWallObstacleAndDoNotShineThroughIt) {
  Scene scene = sceneWith({});
  const std::array<Eigen::Vector2d, 4> wall{{{3.0, -3.0}, {3.3, -3.0}, {3.3, 3.0}, {3.0, 3.0}}};
  scene.obstacles.push_back({"wall", *ConvexPolygon::fromPoints(wall)});
  const World world(std::move(scene));
  const Drawn d = drawFrameOf(world);
  const auto obstacle = d.canvas.fillsOf(Palette{}.obstacle);
  ASSERT_EQ(obstacle.size(), 1u);
  const auto beams = d.canvas.fillsOf(beamColor());
  ASSERT_FALSE(beams.empty());
  for (const auto& b : beams) EXPECT_LT(b.order, obstacle.front().order) << "a beam over the wall";
  EXPECT_LE(beamReach(d).second, 3.0 + 1e-3) << "light through the wall";
}

TEST(Headlights, BeamsStopAtTheLotsWalls) {
  Scene scene = sceneWith({});
  scene.bounds = Aabb2{{-10.0, -10.0}, {4.0, 10.0}};
  const World world(std::move(scene));
  const Drawn d = drawFrameOf(world);
  const auto walls = d.canvas.fillsOf(Palette{}.wall);
  ASSERT_FALSE(walls.empty());
  const auto beams = d.canvas.fillsOf(beamColor());
  ASSERT_FALSE(beams.empty());
  for (const auto& b : beams) EXPECT_LT(b.order, walls.front().order) << "a beam over a wall";
  EXPECT_LE(beamReach(d).second, 4.0 + 1e-3) << "light beyond the walls";
}

}  // namespace
}  // namespace cardemo
