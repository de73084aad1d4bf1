// Continuous collision in World: no tunnelling through a parked car or a 5 cm kerb at any speed
// up to 1000 m/s, at every phase of the obstacle against the per-step grid of positions, at 30 to
// 480 Hz, at several approach angles, reversing and turning (lab/tests/sim compares the study's
// other detection schemes).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "collision/narrow_phase.hpp"
#include "drive_into.hpp"
#include "geometry/angle.hpp"
#include "key_frames.hpp"
#include "scene_builders.hpp"
#include "sim/world.hpp"

namespace cardemo {
namespace {

using testing::kNone;

using test::carAcross;
using test::driveInto;
using test::kerbAcross;
using test::kResting;
using test::sceneFor;
using test::Target;

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
              const std::string failure = driveInto(t, heading, speed, hz, nullptr, kNone, frames);
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
          ASSERT_EQ(driveInto(t, 37.0, speed, hz, nullptr, kNone, frames, far), "")
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
          const std::string failure =
              driveInto(t, 0.0, -speed, hz, nullptr, InputFrame{false, true, false, false}, frames);
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
