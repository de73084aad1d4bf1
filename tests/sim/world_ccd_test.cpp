// Continuous collision in World: no tunnelling through a parked car or a 5 cm kerb at any speed
// up to 1000 m/s, at every phase of the obstacle against the per-step grid of positions, at 30 to
// 480 Hz, at several approach angles, reversing and turning; and the three detection modes.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "collision/narrow_phase.hpp"
#include "geometry/angle.hpp"
#include "key_frames.hpp"
#include "scene_builders.hpp"
#include "sim/world.hpp"

namespace cardemo {
namespace {

using testing::kNone;

constexpr double kResting = 1e-4;  // restingPenetration near the origin

// A wall-like obstacle centred `distance` ahead of the player along `heading_deg`, its face turned
// by `face_deg` from square to the path: a 5 cm x 12 m kerb, or a parked car lying across.
struct Target {
  StaticShape shape;
  Eigen::Vector2d centre;
  Eigen::Vector2d normal;  // unit, facing the player's start
};

Target kerbAcross(double heading_deg, double face_deg, double distance) {
  const Eigen::Vector2d dir = unitFromDegrees(heading_deg);
  const Eigen::Vector2d centre = dir * distance;
  const Obb2 box = Obb2::fromDegrees(centre, heading_deg + face_deg, 0.05, 12.0);
  return {ConvexPolygon::fromObb(box), centre, -unitFromDegrees(heading_deg + face_deg)};
}

Target carAcross(double heading_deg, double face_deg, double distance) {
  const Eigen::Vector2d dir = unitFromDegrees(heading_deg);
  const Eigen::Vector2d centre = dir * distance;
  // Length across the path, so the 1.8 m width is what the player has to cross.
  const Obb2 box = Obb2::fromDegrees(centre, heading_deg + face_deg + 90.0, 4.5, 1.8);
  return {box, centre, -unitFromDegrees(heading_deg + face_deg)};
}

Scene sceneFor(const Target& t, double heading_deg, double speed) {
  Scene s = test::sceneWith({}, 0.0, 0.0, heading_deg);
  s.player.speed = speed;
  if (const Obb2* box = std::get_if<Obb2>(&t.shape)) {
    s.parked.push_back({"target", *box, 0.0});
  } else {
    s.obstacles.push_back({"target", std::get<ConvexPolygon>(t.shape)});
  }
  return s;
}

// Drives into the target and checks every frame: never deeper than the resting margin allows,
// the centre never on the far side; a hit on the target.
std::string driveInto(const Target& target, double heading_deg, double speed, double hz,
                      CollisionDetection mode, const InputFrame& input, int frames,
                      const Eigen::Vector2d& offset = Eigen::Vector2d::Zero()) {
  WorldSettings settings;
  settings.hz = hz;
  settings.schemes.collision = mode;
  World world(test::translated(sceneFor(target, heading_deg, speed), offset), settings);
  std::ostringstream why;
  for (int f = 0; f < frames; ++f) {
    world.step(input);
    const double side = (world.car().position - offset - target.centre).dot(target.normal);
    const double sep = collidePlayer(world.carBox(), world.colliders().shape(0)).separation;
    if (side <= 0.0 || sep < -2.0 * kResting - 1e-9) {
      why << "frame " << world.frame() << ": centre " << side << " m in front of the target, sep "
          << sep;
      return why.str();
    }
  }
  if (world.hits().empty()) return "no hit";
  if (world.hits()[0].id != "target") return "hit the wrong thing";
  return "";
}

TEST(WorldContinuous, NoTunnellingAtAnySpeedPhaseRateOrAngle) {
  int runs = 0;
  for (const double hz : {30.0, 60.0, 120.0, 240.0, 480.0}) {
    for (const double speed : {120.0, 300.0, 700.0, 1000.0}) {
      const double step = speed / hz;
      for (const double face : {0.0, 30.0, -55.0}) {
        for (const double heading : {0.0, 37.0}) {
          for (int phase = 0; phase < 8; ++phase) {
            const double distance = 12.0 + step * (phase / 8.0);
            const int frames = static_cast<int>(std::ceil(40.0 / step)) + 3;
            for (const bool kerb : {true, false}) {
              const Target t =
                  kerb ? kerbAcross(heading, face, distance) : carAcross(heading, face, distance);
              const std::string failure =
                  driveInto(t, heading, speed, hz, CollisionDetection::kContinuous, kNone, frames);
              ASSERT_EQ(failure, "")
                  << (kerb ? "kerb" : "car") << " hz " << hz << " speed " << speed << " face "
                  << face << " heading " << heading << " phase " << phase;
              ++runs;
            }
          }
        }
      }
    }
  }
  EXPECT_EQ(runs, 5 * 4 * 3 * 2 * 8 * 2);
}

TEST(WorldContinuous, NoTunnellingFarFromTheOrigin) {
  // The same approaches 1e7 m out: the sweep works relative to the car, so nothing changes.
  const Eigen::Vector2d far{1e7, -1e7};
  for (const double hz : {30.0, 480.0}) {
    for (const double speed : {300.0, 1000.0}) {
      const double step = speed / hz;
      for (int phase = 0; phase < 8; ++phase) {
        for (const bool kerb : {true, false}) {
          const double distance = 12.0 + step * (phase / 8.0);
          const Target t =
              kerb ? kerbAcross(37.0, 30.0, distance) : carAcross(37.0, 30.0, distance);
          const int frames = static_cast<int>(std::ceil(40.0 / step)) + 3;
          ASSERT_EQ(
              driveInto(t, 37.0, speed, hz, CollisionDetection::kContinuous, kNone, frames, far),
              "")
              << (kerb ? "kerb" : "car") << " hz " << hz << " speed " << speed << " phase "
              << phase;
        }
      }
    }
  }
}

TEST(WorldContinuous, NoTunnellingWhileReversing) {
  for (const double hz : {30.0, 120.0, 480.0}) {
    for (const double speed : {200.0, 1000.0}) {
      for (int phase = 0; phase < 8; ++phase) {
        const double step = speed / hz;
        // Facing +x, moving backwards towards -x: the target lies behind.
        const double distance = 12.0 + step * (phase / 8.0);
        for (const bool kerb : {true, false}) {
          const Target t =
              kerb ? kerbAcross(180.0, 10.0, distance) : carAcross(180.0, 0.0, distance);
          const int frames = static_cast<int>(std::ceil(40.0 / step)) + 3;
          const std::string failure = driveInto(t, 0.0, -speed, hz, CollisionDetection::kContinuous,
                                                InputFrame{false, true, false, false}, frames);
          ASSERT_EQ(failure, "") << (kerb ? "kerb" : "car") << " hz " << hz << " speed " << speed
                                 << " phase " << phase;
        }
      }
    }
  }
}

TEST(WorldContinuous, NoTunnellingWhileTurningFast) {
  // A nimble car (no lock narrowing, instant steering, short wheelbase) turning hard at speed:
  // the heading changes by up to a radian per step, so the rotation is sub-stepped. A long kerb
  // crosses its circle; the car must meet it, never cross it.
  std::int64_t substeps = 0;
  for (const double hz : {30.0, 60.0, 120.0}) {
    for (const double speed : {60.0, 150.0}) {
      for (int phase = 0; phase < 8; ++phase) {
        WorldSettings settings;
        settings.hz = hz;
        settings.car.lock_speed = 0.0;  // no narrowing
        settings.car.steer_rate = 100.0;
        settings.car.max_steer = 0.5;
        settings.car.wheelbase = 2.7;
        settings.car.drag = 0.0;
        settings.car.grip = 1e9;  // no grip limit on the lock
        // Turning circle radius 2.7 / tan(0.5) = 4.95 m (a polygon of long chords at 30 Hz). The
        // kerb is placed where the free car's boxes reach past it, so it must be met.
        const int frames = 3 * static_cast<int>(hz);
        double reach = -1e9;
        {
          Scene free = test::sceneWith({});
          free.player.speed = speed;
          World w(free, settings);
          for (int f = 0; f < frames; ++f) {
            w.step(InputFrame{false, false, true, false});
            reach = std::max(reach, w.carBox().aabb().max.x());
          }
        }
        const double x = reach - 0.3 - 0.1 * phase;
        Scene scene = test::sceneWith({});
        scene.player.speed = speed;
        const Obstacle kerb = test::wallObstacle("kerb", x, -20.0, x + 0.05, 20.0);
        scene.obstacles.push_back(kerb);
        World world(scene, settings);
        for (int f = 0; f < frames; ++f) {
          world.step(InputFrame{false, false, true, false});
          const double sep = collidePlayer(world.carBox(), kerb.polygon).separation;
          ASSERT_GE(sep, -2.0 * kResting - 1e-9) << "hz " << hz << " speed " << speed << " phase "
                                                 << phase << " frame " << world.frame();
          ASSERT_LT(world.car().position.x(), x);
        }
        ASSERT_FALSE(world.hits().empty()) << "hz " << hz << " speed " << speed;
        EXPECT_EQ(world.hits()[0].id, "kerb");
        substeps += world.stats().substeps;
      }
    }
  }
  EXPECT_GT(substeps, 0) << "the rotation was never sub-stepped";
}

TEST(WorldContinuous, SlowStepsTakeTheDiscretePathExactly) {
  // At ordinary speeds the three modes agree bit for bit and nothing is swept or sub-stepped.
  const Scene scene = test::parkingLot(13);
  WorldSettings continuous, substepped, discrete;
  substepped.schemes.collision = CollisionDetection::kSubstepped;
  discrete.schemes.collision = CollisionDetection::kDiscrete;
  World a(scene, continuous), b(scene, substepped), c(scene, discrete);
  for (const InputFrame& in : test::scriptedDrive(13, 3000)) {
    a.step(in);
    b.step(in);
    c.step(in);
    ASSERT_EQ(a.stateHash(), b.stateHash()) << "frame " << a.frame();
    ASSERT_EQ(a.stateHash(), c.stateHash()) << "frame " << a.frame();
  }
  EXPECT_GT(a.hits().size(), 0u);
  EXPECT_EQ(a.stats().sweeps, 0);
  EXPECT_EQ(a.stats().substeps, 0);
  EXPECT_EQ(b.stats().substeps, 0);
}

TEST(WorldContinuous, DiscreteModeTunnelsWhereTheOthersDoNot) {
  // 300 m/s at 30 Hz: 10 m per step over a 5 cm kerb.
  const Target t = kerbAcross(0.0, 0.0, 25.0);
  EXPECT_NE(driveInto(t, 0.0, 300.0, 30.0, CollisionDetection::kDiscrete, kNone, 10), "");
  EXPECT_EQ(driveInto(t, 0.0, 300.0, 30.0, CollisionDetection::kSubstepped, kNone, 10), "");
  EXPECT_EQ(driveInto(t, 0.0, 300.0, 30.0, CollisionDetection::kContinuous, kNone, 10), "");
}

TEST(WorldContinuous, FirstContactIsAtTheTimeOfImpact) {
  // Head-on at 1000 m/s and 30 Hz into a kerb 40 m ahead: the car stops with its front at the
  // kerb's face, in resting contact, instead of wherever a sub-step happened to land.
  const Target t = kerbAcross(0.0, 0.0, 40.0);
  WorldSettings settings;
  settings.hz = 30.0;
  World world(sceneFor(t, 0.0, 1000.0), settings);
  while (world.hits().empty() && world.frame() < 10) world.step(kNone);
  ASSERT_EQ(world.hits().size(), 1u);
  const double sep = collidePlayer(world.carBox(), t.shape).separation;
  EXPECT_LE(sep, 0.0);
  EXPECT_GE(sep, -2.0 * kResting);
  EXPECT_GT(world.stats().sweeps, 0);
  EXPECT_EQ(world.stats().substeps, 0);
}

}  // namespace
}  // namespace cardemo
