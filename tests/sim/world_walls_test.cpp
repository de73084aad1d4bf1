// The scene's bounds are walls that damage as obstacles do: a hit per first contact, named for
// the edge, costing by the closing speed above the threshold, one crash per crash window.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "key_frames.hpp"
#include "scene_builders.hpp"
#include "sim/contact_response.hpp"
#include "sim/walls.hpp"
#include "sim/world.hpp"

namespace cardemo {
namespace {

using test::sceneWith;
using testing::kNone;
using testing::kUp;

constexpr double kCarHalfLength = 2.25;  // the default 4.5 m car
const Aabb2 kWallLot{{-20.0, -10.0}, {20.0, 10.0}};

struct WallDrive {
  WallSide side;
  double heading_deg;     // facing the wall
  Eigen::Vector2d start;  // `gap` metres short of it, centred on the other axis
};

WallDrive wallCase(WallSide side, double gap) {
  const double dx = 20.0 - kCarHalfLength - gap;
  const double dy = 10.0 - kCarHalfLength - gap;
  switch (side) {
    case WallSide::kWest:
      return {side, 180.0, {-dx, 0.0}};
    case WallSide::kEast:
      return {side, 0.0, {dx, 0.0}};
    case WallSide::kSouth:
      return {side, 270.0, {0.0, -dy}};
    case WallSide::kNorth:
      break;
  }
  return {side, 90.0, {0.0, dy}};
}

// Rolls into the wall at `speed` (m/s) from `gap` metres, no key held, for 2 s.
World rollInto(const WallDrive& c, double speed) {
  Scene scene = sceneWith({}, c.start.x(), c.start.y(), c.heading_deg);
  scene.bounds = kWallLot;
  scene.player.speed = speed;
  World world(std::move(scene));
  for (int f = 0; f < 240; ++f) world.step(kNone);
  return world;
}

int wallDamage(double speed) {
  const WorldSettings s;
  if (speed < s.damage_threshold) return 0;
  return std::clamp(static_cast<int>(std::ceil(s.damage_per_mps * speed - 1e-9)), s.damage_min,
                    s.damage_max);
}

TEST(Walls, IdsAndNormalsNameEachEdge) {
  EXPECT_EQ(wallId(WallSide::kWest), "bounds-west");
  EXPECT_EQ(wallId(WallSide::kEast), "bounds-east");
  EXPECT_EQ(wallId(WallSide::kSouth), "bounds-south");
  EXPECT_EQ(wallId(WallSide::kNorth), "bounds-north");
  EXPECT_EQ(wallNormal(WallSide::kWest), Eigen::Vector2d(-1.0, 0.0));
  EXPECT_EQ(wallNormal(WallSide::kNorth), Eigen::Vector2d(0.0, 1.0));
  const auto depth = wallDepths({{-20.5, -9.0}, {19.0, 10.0}}, kWallLot);
  EXPECT_EQ(depth[0], 0.5);   // past the west wall
  EXPECT_EQ(depth[1], -1.0);  // 1 m short of the east one
  EXPECT_EQ(depth[2], -1.0);
  EXPECT_EQ(depth[3], 0.0);  // exactly touching the north one
}

TEST(Walls, FastIntoEachWallIsOneDamagingHit) {
  for (const WallSide side : kWallSides) {
    const WallDrive c = wallCase(side, 0.5);
    const World world = rollInto(c, 6.0);
    ASSERT_EQ(world.hits().size(), 1u) << wallId(side);
    const HitEvent& hit = world.hits()[0];
    EXPECT_EQ(hit.id, wallId(side));
    EXPECT_EQ(hit.collider, world.wallIndex(side));
    EXPECT_TRUE(world.isWall(hit.collider));
    EXPECT_GT(hit.speed, 5.0);  // 6 m/s less 0.5 m of engine braking
    EXPECT_LT(hit.speed, 6.0);
    EXPECT_EQ(hit.damage, wallDamage(hit.speed)) << wallId(side);
    EXPECT_EQ(world.health(), 100 - hit.damage);
    EXPECT_EQ(world.damagingCrashes(), 1);
    // It bounced off (20 %) and rolled back out of contact.
    EXPECT_TRUE(world.contacts().empty()) << wallId(side);
  }
}

TEST(Walls, SlowIntoEachWallIsAHitWithoutDamage) {
  for (const WallSide side : kWallSides) {
    const World world = rollInto(wallCase(side, 0.02), 0.6);
    ASSERT_EQ(world.hits().size(), 1u) << wallId(side);
    EXPECT_EQ(world.hits()[0].id, wallId(side));
    EXPECT_LT(world.hits()[0].speed, WorldSettings{}.damage_threshold);
    EXPECT_EQ(world.hits()[0].damage, 0);
    EXPECT_EQ(world.health(), 100);
    EXPECT_EQ(world.damagingCrashes(), 0);
  }
}

TEST(Walls, HeldAgainstAWallStaysOneContactAndOneHit) {
  // From 2 cm away the car meets the wall under 1 m/s, too slow to bounce off it.
  const WallDrive c = wallCase(WallSide::kEast, 0.02);
  Scene scene = sceneWith({}, c.start.x(), c.start.y(), c.heading_deg);
  scene.bounds = kWallLot;
  World world(std::move(scene));
  for (int f = 0; f < 600; ++f) {
    world.step(kUp);
    if (!world.hits().empty()) {
      ASSERT_EQ(world.contacts().size(), 1u) << "frame " << f;
    }
  }
  ASSERT_EQ(world.hits().size(), 1u);
  // Pressed against it at the resting penetration, as against a collider.
  EXPECT_NEAR(world.carBox().aabb().max.x(), 20.0 + restingPenetration(world.car().position),
              1e-12);
}

TEST(Walls, ASlideAlongAWallIsOneHit) {
  // Nose 19 degrees into the north wall at full throttle for 3 s: it slides along it, touching it
  // every frame from the first contact on.
  Scene scene = sceneWith({}, -15.0, 0.0, 19.0);
  const double reach = 2.25 * std::sin(19.0 * std::numbers::pi / 180.0) +
                       0.9 * std::cos(19.0 * std::numbers::pi / 180.0);
  scene.bounds = Aabb2{{-200.0, -50.0}, {200.0, reach + 0.05}};
  World world(std::move(scene));
  for (int f = 0; f < 360; ++f) world.step(kUp);
  ASSERT_EQ(world.hits().size(), 1u);
  EXPECT_EQ(world.hits()[0].id, "bounds-north");
  EXPECT_EQ(world.hits()[0].damage, 0);  // it met the wall at well under 1 m/s across it
  ASSERT_EQ(world.contacts().size(), 1u);
  EXPECT_GT(world.car().velocity().x(), 8.0);
  // Sliding along it faster than 1 m/s scrapes, as along a kerb: 4 points a second.
  EXPECT_GT(world.scrapeDamage(), 0);
  EXPECT_EQ(world.health(), 100 - world.scrapeDamage());
}

TEST(Walls, ACornerTouchingTwoWallsIsTwoHits) {
  // Heading into the south-west corner at 45 degrees, the box reaches both walls at once.
  const double reach = (kCarHalfLength + 0.9) * std::sqrt(0.5);
  Scene scene = sceneWith({}, -20.0 + reach + 0.3, -10.0 + reach + 0.3, 225.0);
  scene.bounds = kWallLot;
  scene.player.speed = 5.0;
  World world(std::move(scene));
  for (int f = 0; f < 240; ++f) world.step(kNone);
  ASSERT_EQ(world.hits().size(), 2u);
  EXPECT_EQ(world.hits()[0].id, "bounds-west");
  EXPECT_EQ(world.hits()[1].id, "bounds-south");
  EXPECT_EQ(world.hits()[0].frame, world.hits()[1].frame);
  EXPECT_EQ(world.crashes(), 2);
  for (const HitEvent& h : world.hits()) {
    EXPECT_GT(h.speed, WorldSettings{}.damage_threshold);
    EXPECT_EQ(h.damage, wallDamage(h.speed));
  }
}

TEST(Walls, AReTouchWithinTheCrashWindowIsTheSameCrash) {
  // Bounce off the east wall and drive straight back into it at once: one crash.
  const WallDrive c = wallCase(WallSide::kEast, 0.5);
  Scene scene = sceneWith({}, c.start.x(), c.start.y(), c.heading_deg);
  scene.bounds = kWallLot;
  scene.player.speed = 6.0;
  World world(std::move(scene));
  while (world.hits().empty()) world.step(kNone);
  // Bounced back, it rolls to a stop; Up then drives it back in (a press at a standstill).
  while (world.car().speed != 0.0) world.step(kNone);
  for (int f = 0; f < 120 && world.hits().size() < 2; ++f) world.step(kUp);
  ASSERT_EQ(world.hits().size(), 2u);
  EXPECT_EQ(world.hits()[1].crash, world.hits()[0].crash);
  EXPECT_EQ(world.crashes(), 1);
}

TEST(Walls, AStartTouchingAWallIsAHitAtFrameZero) {
  Scene scene = sceneWith({}, 20.0 - kCarHalfLength, 0.0, 0.0);
  scene.bounds = kWallLot;
  const World world(std::move(scene));
  ASSERT_EQ(world.hits().size(), 1u);
  EXPECT_EQ(world.hits()[0].frame, 0);
  EXPECT_EQ(world.hits()[0].id, "bounds-east");
  EXPECT_EQ(world.hits()[0].damage, 0);
}

TEST(Walls, NoBoundsNoWalls) {
  Scene scene = sceneWith({}, 0.0, 0.0, 0.0);
  scene.player.speed = 30.0;
  World world(std::move(scene));
  for (int f = 0; f < 600; ++f) world.step(kUp);
  EXPECT_TRUE(world.hits().empty());
}

}  // namespace
}  // namespace cardemo
