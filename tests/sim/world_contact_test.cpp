// Contacts that slide: friction on walls and colliders, and no snag on the seams of a row.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "key_frames.hpp"
#include "scene_builders.hpp"
#include "sim/world.hpp"

namespace cardemo {
namespace {

using testing::kNone;
using testing::kUp;

using test::parkedCar;
using test::sceneWith;

double degrees(double d) {
  return d * std::numbers::pi / 180.0;
}

TEST(WorldContact, FullThrottleAlongAWallAtNineteenDegreesSlidesAlongIt) {
  // The car's nose points 19 degrees into the top wall. Along the wall the engine gives
  // a cos(19) and the wall's friction takes mu a sin(19) (the normal part of the push); rolling
  // resistance acts along the heading like the engine, so the speed after t (no drag) is
  // (engine - rolling) (cos - mu sin) t.
  Scene scene = sceneWith({}, 0.0, 0.0, 19.0);
  const double theta = degrees(19.0);
  const double reach = 2.25 * std::sin(theta) + 0.9 * std::cos(theta);
  scene.bounds = Aabb2{{-200.0, -50.0}, {200.0, reach + 0.05}};
  WorldSettings settings;
  settings.car.drag = 0.0;
  World world(scene, settings);
  const double seconds = 3.0;
  for (int f = 0; f < 120 * 3; ++f) world.step(kUp);
  const CarParams& p = settings.car;
  const double expected = (p.engine_accel - p.rolling_resistance) *
                          (std::cos(theta) - p.contact_friction * std::sin(theta)) * seconds;
  const Eigen::Vector2d v = world.car().velocity();
  EXPECT_NEAR(v.x(), expected, 0.03 * expected);  // about 35 km/h, not the former 1 km/h
  EXPECT_NEAR(v.y(), 0.0, 1e-9);
  EXPECT_TRUE(world.hits().empty());
  EXPECT_EQ(world.health(), 100);
  EXPECT_NEAR(world.carBox().aabb().max.y(), reach + 0.05, 1e-9);
}

TEST(WorldContact, ShallowGlanceOffAParkedCarKeepsMostOfItsSpeed) {
  // 10 m/s at 15 degrees onto the long side of a parked car: the normal part (2.59 m/s) bounces
  // back 20 %, the sliding part (9.66 m/s) loses mu times the normal change.
  const double theta = degrees(15.0);
  Scene scene = sceneWith({parkedCar("side", 0.0, 0.0, 0.0, 20.0, 1.8)}, -8.0, 3.0, -15.0);
  scene.player.speed = 10.0;
  WorldSettings settings;
  settings.car.drag = 0.0;
  settings.car.rolling_resistance = 0.0;
  settings.car.engine_brake = 0.0;
  World world(scene, settings);
  while (world.hits().empty() && world.frame() < 240) world.step(kNone);
  ASSERT_EQ(world.hits().size(), 1u);
  const CarParams& p = settings.car;
  const double vn = 10.0 * std::sin(theta);
  const double k = (1.0 + p.restitution) * vn;
  const double along = 10.0 * std::cos(theta) - p.contact_friction * k;
  const Eigen::Vector2d v = world.car().velocity();
  EXPECT_NEAR(v.x(), along, 1e-9);
  EXPECT_NEAR(v.y(), p.restitution * vn, 1e-9);
  EXPECT_GT(v.norm(), 0.87 * 10.0);
  EXPECT_EQ(world.hits()[0].damage, 8);  // ceil(3 * 2.59)
  // Its nose still points into the car: once the bounce has carried it clear, the slip decays, the
  // car comes back onto the side (a second, gentle touch of the same crash) and slides along it.
  for (int f = 0; f < 60; ++f) world.step(kNone);
  EXPECT_GT(world.car().velocity().norm(), 0.8 * 10.0);
  ASSERT_LE(world.hits().size(), 2u);
  EXPECT_EQ(world.hits().back().crash, 1);
  EXPECT_EQ(world.health(), 100 - 8 - world.scrapeDamage());
}

// A row of parked cars along +x, the player just above it, nose 2 degrees down into the row.
Scene row(double gap) {
  std::vector<ParkedCar> cars;
  for (int i = 0; i < 6; ++i) {
    cars.push_back(parkedCar("R" + std::to_string(i), 4.5 * i + gap * i, 0.0, 0.0));
  }
  Scene scene = sceneWith(std::move(cars), -6.0, 1.9, -2.0);
  scene.player.speed = 8.0;
  return scene;
}

TEST(WorldContact, GrazingARowOfParkedCarsDoesNotSnagOnTheSeams) {
  for (const double gap : {0.0, 0.05, 0.3}) {
    World world(row(gap));
    double slowest = 1e9;
    for (int f = 0; f < 120 * 3 && world.car().position.x() < 25.0; ++f) {
      world.step(kUp);
      if (world.car().position.x() > 0.0) slowest = std::min(slowest, world.car().velocity().x());
    }
    EXPECT_GT(world.car().position.x(), 25.0) << "gap " << gap;
    EXPECT_GT(slowest, 7.0) << "gap " << gap;
    // One first contact per car at most, each a gentle one.
    EXPECT_LE(world.hits().size(), 6u) << "gap " << gap;
    for (const HitEvent& h : world.hits()) EXPECT_LT(h.speed, 1.0) << h.id << " gap " << gap;
  }
}

}  // namespace
}  // namespace cardemo
