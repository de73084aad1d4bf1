#include "sim/world.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "geometry/sat_obb2.hpp"
#include "key_frames.hpp"
#include "scene_builders.hpp"

namespace cardemo {
namespace {

using testing::kLeft;
using testing::kNone;
using testing::kUp;

using test::parkedCar;
using test::sceneWith;

int expectedDamage(const WorldSettings& s, double speed) {
  if (speed < s.damage_threshold) return 0;
  return std::clamp(static_cast<int>(std::ceil(s.damage_per_mps * speed)), s.damage_min,
                    s.damage_max);
}

TEST(World, HeadOnHitIsReportedOnceAtTheFirstFrameOfContact) {
  WorldSettings settings;
  settings.car.restitution = 0.0;
  const Scene scene =
      sceneWith({parkedCar("A1", 20.0, 0.4, 90.0), parkedCar("far", 200.0, 0.0, 0.0)});
  World world(scene, settings);
  ASSERT_TRUE(world.hits().empty());

  // Brute-force twin: the free car (no collisions at all) checked against every parked car.
  CarParams params = settings.car;
  CarState free_car = world.car();
  std::int64_t first_overlap = -1;
  double speed_at_overlap = 0.0;
  for (std::int64_t f = 1; f <= 1200; ++f) {
    world.step(kUp);
    if (first_overlap < 0) {
      free_car = integrateCar(free_car, kUp, params, 1.0 / settings.hz);
      for (const ParkedCar& p : scene.parked) {
        if (overlapObb2(carBox(free_car, params), p.box)) {
          first_overlap = f;
          speed_at_overlap = free_car.speed;
        }
      }
      if (first_overlap < 0) {
        ASSERT_TRUE(world.hits().empty()) << "hit before any overlap at frame " << f;
        ASSERT_EQ(world.car().position, free_car.position) << "frame " << f;
      }
    }
    for (const ParkedCar& p : scene.parked) {
      ASSERT_GE(collideObb2(world.carBox(), p.box).separation, -1.01e-4)
          << "penetrating at frame " << f;
    }
  }
  ASSERT_GT(first_overlap, 0);
  ASSERT_EQ(world.hits().size(), 1u) << "holding throttle against the car must not add hits";
  const HitEvent& hit = world.hits()[0];
  EXPECT_EQ(hit.frame, first_overlap);
  EXPECT_EQ(hit.id, "A1");
  EXPECT_EQ(hit.collider, 0u);
  EXPECT_NEAR(hit.speed, speed_at_overlap, 1e-12);  // head-on: the normal is the heading
  EXPECT_EQ(hit.damage, expectedDamage(settings, speed_at_overlap));
  EXPECT_EQ(world.health(), 100 - hit.damage);
  // Still pressed against it: touching, not separated.
  ASSERT_EQ(world.contacts().size(), 1u);
  EXPECT_TRUE(overlapObb2(world.carBox(), scene.parked[0].box));
}

TEST(World, BouncesSettleAndRestingContactAddsNoHits) {
  const Scene scene = sceneWith({parkedCar("A1", 15.0, 0.0, 90.0)});
  World world(scene);  // default restitution: a few bounces, then rest
  for (int f = 0; f < 120 * 4; ++f) world.step(kUp);
  const std::size_t settled = world.hits().size();
  ASSERT_GE(settled, 1u);
  // Impacts below the bounce threshold do not bounce, so the hops end after a few hits.
  ASSERT_LE(settled, 3u);
  for (int f = 0; f < 120 * 10; ++f) {
    world.step(kUp);
    ASSERT_EQ(world.hits().size(), settled) << "new hit while resting at frame " << world.frame();
    ASSERT_EQ(world.contacts().size(), 1u) << "contact flickered at frame " << world.frame();
    ASSERT_GE(collideObb2(world.carBox(), scene.parked[0].box).separation, -1.01e-4);
  }
}

TEST(World, TouchingAtFrameZeroIsAHitAtFrameZero) {
  // Exactly touching: the parked car's rear face is the player's front face.
  const Scene scene = sceneWith({parkedCar("T", 4.5, 0.0, 0.0), parkedCar("clear", 9.1, 0.0, 0.0)});
  World world(scene);
  ASSERT_EQ(world.hits().size(), 1u);
  EXPECT_EQ(world.hits()[0].frame, 0);
  EXPECT_EQ(world.hits()[0].id, "T");
  EXPECT_EQ(world.hits()[0].speed, 0.0);
  EXPECT_EQ(world.hits()[0].damage, 0);  // no closing speed: below the damage threshold
  EXPECT_EQ(world.health(), 100);
  EXPECT_EQ(world.stats().contacts, 1);
  for (int f = 0; f < 100; ++f) world.step(kNone);
  EXPECT_EQ(world.hits().size(), 1u);
  EXPECT_EQ(world.contacts().size(), 1u);
}

TEST(World, OverlappingAtFrameZeroIsPushedOutWithoutASecondHit) {
  const Scene scene = sceneWith({parkedCar("O", 3.0, 0.5, 30.0)});
  World world(scene);
  ASSERT_EQ(world.hits().size(), 1u);
  EXPECT_EQ(world.hits()[0].frame, 0);
  world.step(kNone);
  EXPECT_GE(collideObb2(world.carBox(), scene.parked[0].box).separation, -1.01e-4);
  for (int f = 0; f < 50; ++f) world.step(kNone);
  EXPECT_EQ(world.hits().size(), 1u);
}

TEST(World, GameOverIgnoresInputAndHealthNeverGoesNegative) {
  Scene scene = sceneWith({parkedCar("A", 8.0, 0.0, 90.0), parkedCar("B", -8.0, 0.0, 90.0)});
  scene.player.health = 3;
  World world(scene);
  for (int f = 0; f < 600 && !world.gameOver(); ++f) world.step(kUp);
  ASSERT_TRUE(world.gameOver());
  EXPECT_EQ(world.health(), 0);
  const std::size_t hits = world.hits().size();
  double last_speed = std::abs(world.car().speed);
  for (int f = 0; f < 120 * 30; ++f) {
    world.step(InputFrame{false, true, true, false});  // reverse-left: must be ignored
    ASSERT_EQ(world.health(), 0);
    ASSERT_EQ(world.car().steer, 0.0);
    ASSERT_LE(std::abs(world.car().speed), last_speed + 1e-12);
    last_speed = std::abs(world.car().speed);
  }
  EXPECT_EQ(world.car().speed, 0.0);
  EXPECT_EQ(world.hits().size(), hits);
}

TEST(World, WallsStopTheCarAndCountAsHits) {
  Scene scene = sceneWith({});
  scene.bounds = Aabb2{{-20.0, -10.0}, {20.0, 10.0}};
  World world(scene);
  // A wall is touched at the resting penetration, as a collider is (0.1 mm here).
  const double rest = 1e-4 + 1e-9;
  for (int f = 0; f < 120 * 8; ++f) {
    world.step(f < 600 ? kUp : InputFrame{true, false, true, false});
    const Aabb2 box = world.carBox().aabb();
    ASSERT_LE(box.max.x(), 20.0 + rest) << "frame " << f;
    ASSERT_GE(box.min.x(), -20.0 - rest);
    ASSERT_LE(box.max.y(), 10.0 + rest);
    ASSERT_GE(box.min.y(), -10.0 - rest);
  }
  ASSERT_FALSE(world.hits().empty());
  for (const HitEvent& h : world.hits()) EXPECT_EQ(h.id.rfind("bounds-", 0), 0u) << h.id;
  EXPECT_EQ(world.hits()[0].id, "bounds-east");
  EXPECT_LT(world.health(), 100);
  EXPECT_NEAR(world.carBox().aabb().max.x(), 20.0, 0.5);  // pressed against the right wall
}

TEST(World, FastCarDoesNotTunnelThroughAParkedCar) {
  Scene scene = sceneWith({parkedCar("thin", 60.0, 0.0, 90.0)});  // 1.8 m thick along the path
  scene.player.speed = 300.0;
  World world(scene);
  for (int f = 0; f < 120; ++f) {
    world.step(kUp);
    ASSERT_LT(world.car().position.x(), 60.0) << "tunnelled at frame " << world.frame();
  }
  ASSERT_EQ(world.hits().size(), 1u);
  EXPECT_EQ(world.hits()[0].id, "thin");
  EXPECT_GT(world.hits()[0].speed, 200.0);
  EXPECT_EQ(world.hits()[0].damage, WorldSettings{}.damage_max);
  EXPECT_GT(world.stats().sweeps, 0);
  EXPECT_LE(world.carBox().aabb().max.x(), 60.0 - 0.9 + 1e-6);
}

TEST(World, FastCarDoesNotTunnelThroughAThinObstacle) {
  Scene scene = sceneWith({});
  scene.obstacles.push_back(test::wallObstacle("kerb", 50.0, -5.0, 50.05, 5.0));
  scene.player.speed = 300.0;
  World world(scene);
  for (int f = 0; f < 120; ++f) {
    world.step(kUp);
    ASSERT_LE(world.carBox().aabb().max.x(), 50.0 + 1.01e-4)
        << "tunnelled at frame " << world.frame();
  }
  ASSERT_EQ(world.hits().size(), 1u);
  EXPECT_EQ(world.hits()[0].id, "kerb");
  EXPECT_EQ(world.hits()[0].collider, 0u);
  EXPECT_GT(world.stats().sweeps, 0);
}

TEST(World, ObstaclesAreIndexedAfterParkedCars) {
  Scene scene = sceneWith({parkedCar("car", 0.0, 30.0, 0.0)});
  scene.obstacles.push_back(test::wallObstacle("block", 10.0, -3.0, 11.0, 3.0));
  WorldSettings settings;
  settings.car.restitution = 0.0;
  World world(scene, settings);
  ASSERT_EQ(world.colliders().size(), 2u);
  EXPECT_EQ(world.colliderId(0), "car");
  EXPECT_EQ(world.colliderId(1), "block");
  for (int f = 0; f < 600; ++f) world.step(kUp);
  ASSERT_EQ(world.hits().size(), 1u);
  EXPECT_EQ(world.hits()[0].collider, 1u);
  EXPECT_EQ(world.hits()[0].id, "block");
  EXPECT_LE(world.carBox().aabb().max.x(), 10.0 + 1.01e-4);
}

TEST(World, NarrowPhaseRunsOnlyOnCandidates) {
  // Empty space: cars exist but far away, so no candidate and no narrow-phase test.
  const Scene far =
      sceneWith({parkedCar("x", 500.0, 500.0, 0.0), parkedCar("y", -500.0, 400.0, 0.0)});
  World empty(far);
  for (const InputFrame& in : test::scriptedDrive(5, 1200)) empty.step(in);
  EXPECT_EQ(empty.stats().narrowphase_tests, 0);
  EXPECT_EQ(empty.stats().broadphase_candidates, 0);
  // Every moved frame still asks the broad phase, mostly answered from the grown box (the drive
  // stands still now and then: a pedal held through a stop holds the car).
  EXPECT_GT(empty.stats().broadphase_queries + empty.stats().reused_queries, 900);
  EXPECT_GT(empty.stats().reused_queries, 10 * empty.stats().broadphase_queries);

  World lot(test::parkingLot(3));
  for (const InputFrame& in : test::scriptedDrive(3, 3000)) lot.step(in);
  EXPECT_GT(lot.stats().narrowphase_tests, 0);
  EXPECT_LE(lot.stats().narrowphase_tests, lot.stats().broadphase_candidates);
}

TEST(World, StationaryCarSkipsBroadPhaseQueries) {
  const Scene scene = sceneWith({parkedCar("near", 4.0, 1.8, 0.0)});
  World world(scene);
  EXPECT_EQ(world.stats().broadphase_queries, 1);
  for (int f = 0; f < 100; ++f) world.step(kNone);
  EXPECT_EQ(world.stats().broadphase_queries, 1);
  EXPECT_EQ(world.stats().skipped_queries, 100);
  EXPECT_EQ(world.stats().narrowphase_tests, world.stats().broadphase_candidates);
  EXPECT_EQ(world.candidates().size(), 1u);
}

TEST(World, RenderingAccessorsFollowTheInput) {
  World world(sceneWith({}));
  EXPECT_EQ(world.lastInput(), kNone);
  EXPECT_FALSE(world.braking());
  EXPECT_FALSE(world.reversing());
  for (int f = 0; f < 120; ++f) world.step(kUp);
  EXPECT_EQ(world.lastInput(), kUp);
  EXPECT_FALSE(world.braking());
  EXPECT_EQ(world.slipSpeed(), 0.0);
  EXPECT_FALSE(world.sliding());
  const InputFrame brake{false, true, false, false};
  world.step(brake);
  EXPECT_EQ(world.lastInput(), brake);
  EXPECT_TRUE(world.braking());
  EXPECT_FALSE(world.reversing());
  while (world.car().speed > 0.0) world.step(brake);
  for (int f = 0; f < 60; ++f) world.step(brake);  // held through the stop: it holds the car
  EXPECT_FALSE(world.reversing());
  world.step(kNone);
  for (int f = 0; f < 60; ++f) world.step(brake);  // a fresh press at a standstill reverses
  EXPECT_TRUE(world.reversing());
  EXPECT_FALSE(world.braking());
  world.step(kUp);  // throttle against the reverse roll brakes
  EXPECT_TRUE(world.braking());
  const InputFrame handbrake{false, false, false, false, true};
  world.step(handbrake);
  EXPECT_TRUE(world.braking());
}

// The skid flag at the grip limit: turning at speed, the wheel settles on the grip lock (below the
// steering lock) and the tyres are at their limit; at walking pace the steering lock binds first.
TEST(World, SlidingWhenTheGripLimitsTheTurn) {
  const InputFrame up_left{true, false, true, false};
  Scene fast = sceneWith({});
  fast.player.speed = 20.0;
  World at_speed(std::move(fast));
  const CarParams p;  // the scene's car: sceneWith sets no parameter
  ASSERT_LT(gripLock(p, 20.0), steeringLock(p, 20.0));
  at_speed.step(up_left);
  EXPECT_FALSE(at_speed.sliding()) << "the wheel has not reached the grip lock yet";
  // The keyboard ramp (0.4 rad/s, growing by 1.3 rad/s^2) reaches the 0.06 rad lock in 17 frames.
  for (int f = 0; f < 30; ++f) at_speed.step(up_left);
  EXPECT_TRUE(at_speed.sliding());
  at_speed.step(kUp);
  EXPECT_FALSE(at_speed.sliding()) << "no steering, no grip limit";

  Scene slow = sceneWith({});
  slow.player.speed = 3.0;
  World walking(std::move(slow));
  ASSERT_GT(gripLock(p, 3.0), steeringLock(p, 3.0));
  for (int f = 0; f < 60; ++f) walking.step(kLeft);
  EXPECT_FALSE(walking.sliding());
}

}  // namespace
}  // namespace cardemo
