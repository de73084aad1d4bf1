// Contacts that slide: friction on walls and colliders, and no snag on the seams of a row.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "collision/narrow_phase.hpp"
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
  // One gentle hit (world_walls_test checks the wall's rules); resting 0.1 mm into the wall.
  EXPECT_EQ(world.hits().size(), 1u);
  EXPECT_NEAR(world.carBox().aabb().max.y(), reach + 0.05 + 1e-4, 1e-9);
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

// A parked car turned by `turn_deg` ahead of the player (at the origin, facing +x at `speed`),
// placed so that its lowest point is `clip` metres inside the player's left side (y = 0.9): driving
// on, the player's nose catches only that much of its corner.
Scene cornerAhead(double turn_deg, double clip, double speed = 10.0) {
  ParkedCar p = parkedCar("corner", 8.0, 0.0, turn_deg);
  double lowest = 1e9;
  for (const Eigen::Vector2d& c : p.box.corners()) lowest = std::min(lowest, c.y());
  p.box.center.y() += 0.9 - clip - lowest;
  Scene scene = sceneWith({p});
  scene.player.speed = speed;
  return scene;
}

TEST(WorldContact, ClippingACornerSlidesPastIt) {
  // The play-test's stuck car: the nose met a parked car's corner, the response took the travel
  // axis as the normal, and the car stayed at 0 km/h with the throttle held. A corner caught by
  // less than corner_slip_depth now pushes the car sideways, and it drives on past.
  // At these turns the parked car's corner is the first point the nose meets (at -10 or 80 degrees
  // the player's corner meets a side sloping away first: a glance that ShallowGlance covers).
  for (const double speed : {1.0, 10.0}) {
    for (const double turn : {-80.0, 0.0, 10.0, 30.0}) {
      for (const double clip : {0.02, 0.1, 0.19}) {
        const Scene scene = cornerAhead(turn, clip, speed);
        World world(scene);
        const std::string where = "speed " + std::to_string(speed) + " turn " +
                                  std::to_string(turn) + " clip " + std::to_string(clip);
        double slowest = 1e9;
        for (int f = 0; f < 120 * 8 && world.car().position.x() < 16.0; ++f) {
          world.step(kUp);
          slowest = std::min(slowest, world.car().speed);
          // In contact exactly when the pose after the step overlaps, where the oracle judges
          // hits: a push that cleared the corner altogether is no contact (dropClearedSlips).
          const double sep = collidePlayer(world.carBox(), scene.parked.front().box).separation;
          ASSERT_EQ(!world.contacts().empty(), sep <= 0.0) << where << " frame " << world.frame();
        }
        ASSERT_FALSE(world.hits().empty()) << where;
        EXPECT_GT(world.car().position.x(), 16.0) << where;
        EXPECT_GT(slowest, 0.9 * speed) << where;
        // Pushed to the right of the corner, by about the clip.
        EXPECT_LT(world.car().position.y(), -0.5 * clip) << where;
        EXPECT_GT(world.car().position.y(), -1.0) << where;
        // A sideways push closes at 0 m/s: the clip does no impact damage.
        for (const HitEvent& h : world.hits()) EXPECT_EQ(h.damage, 0) << where;
      }
    }
  }
}

TEST(WorldContact, CatchingMoreThanACornerIsStillACrash) {
  // Past corner_slip_depth the nose hits the car: the response stops the forward motion.
  for (const double turn : {-80.0, 0.0, 10.0}) {
    World world(cornerAhead(turn, 0.3));
    while (world.hits().empty() && world.frame() < 240) world.step(kUp);
    const std::string where = "turn " + std::to_string(turn);
    ASSERT_EQ(world.hits().size(), 1u) << where;
    EXPECT_GT(world.hits().front().damage, 0) << where;
    EXPECT_LT(world.car().velocity().x(), 3.0) << where;
  }
}

TEST(WorldContact, CornerSlipDepthZeroKeepsTheHeadOnResponse) {
  // The setting is the only switch: at 0 the clipped corner stops the car as it used to.
  WorldSettings settings;
  settings.corner_slip_depth = 0.0;
  World world(cornerAhead(0.0, 0.1), settings);
  for (int f = 0; f < 120 * 2; ++f) world.step(kUp);
  EXPECT_LT(world.car().position.x(), 8.0);
}

TEST(WorldContact, CornerSlipIsMirrorSymmetric) {
  // The same clip on the right side slides the car to the left, to the last bit.
  for (const double turn : {-80.0, 10.0}) {
    Scene left = cornerAhead(turn, 0.1);
    Scene right = left;
    for (ParkedCar& p : right.parked) {
      p.box.center.y() = -p.box.center.y();
      p.box.axis.y() = -p.box.axis.y();
    }
    World a(left), b(right);
    for (int f = 0; f < 120; ++f) {
      a.step(kUp);
      b.step(kUp);
      ASSERT_EQ(a.car().position.x(), b.car().position.x()) << "turn " << turn << " frame " << f;
      ASSERT_EQ(a.car().position.y(), -b.car().position.y()) << "turn " << turn << " frame " << f;
    }
    EXPECT_EQ(a.hits().size(), b.hits().size());
  }
}

}  // namespace
}  // namespace cardemo
