#pragma once
// Properties every car integrator must keep (the speed law's stops and caps, the steering, the
// exact axis directions, the heading wrap), as value-parameterised tests: tests/sim/car_test.cpp
// runs them on the game's integrator, lab/tests/sim/car_integrators_test.cpp on the lab's.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <ostream>
#include <string>

#include "geometry/angle.hpp"
#include "key_frames.hpp"
#include "sim/car.hpp"

namespace cardemo::testing {

inline constexpr double kDt = 1.0 / 120.0;

// No drag, rolling resistance or engine braking: the speed law is the driver's command alone.
inline CarParams frictionless() {
  CarParams p;
  p.drag = 0.0;
  p.rolling_resistance = 0.0;
  p.engine_brake = 0.0;
  return p;
}

// One integrator: its test name and its scheme (null: the game's).
struct IntegratorCase {
  const char* name;
  CarStepScheme scheme;
};

// Printed as its name: a test's name then does not depend on where the scheme was loaded.
inline void PrintTo(const IntegratorCase& c, std::ostream* os) {
  *os << c.name;
}

// The suite's test names end in the integrator's name.
inline std::string integratorName(const ::testing::TestParamInfo<IntegratorCase>& info) {
  return info.param.name;
}

class EveryIntegrator : public ::testing::TestWithParam<IntegratorCase> {
 protected:
  // integrateCar with the integrator under test.
  [[nodiscard]] CarState step(const CarState& s, const InputFrame& in, const CarParams& p,
                              double dt) const {
    return integrateCar(s, in, p, dt, GetParam().scheme);
  }
};

TEST_P(EveryIntegrator, ExactAxisDirectionSurvivesStraightDriving) {
  const CarParams p = CarParams{};
  CarState s;
  s.heading = wrapRadians(90.0 * std::numbers::pi / 180.0);
  s.direction = unitFromDegrees(90.0);
  ASSERT_EQ(s.direction, Eigen::Vector2d(0.0, 1.0));
  for (int i = 0; i < 2000; ++i) s = step(s, i < 1000 ? kUp : kDown, p, kDt);
  EXPECT_EQ(s.direction, Eigen::Vector2d(0.0, 1.0));
  EXPECT_EQ(s.position.x(), 0.0);
  EXPECT_GT(s.position.y(), 10.0);
}

TEST_P(EveryIntegrator, BrakingStopsExactlyAtZeroThenReverses) {
  const CarParams p = CarParams{};
  CarState s;
  s.speed = 5.0;
  int stopped_at = -1;
  for (int i = 0; i < 200; ++i) {
    const double before = s.speed;
    s = step(s, kDown, p, kDt);
    if (before > 0.0) {
      ASSERT_GE(s.speed, 0.0) << "braking must not cross zero";
      if (s.speed == 0.0) stopped_at = i;
    } else {
      ASSERT_LT(s.speed, 0.0) << "from standstill D reverses";
    }
  }
  ASSERT_GE(stopped_at, 0);
  EXPECT_LT(s.speed, 0.0);
  // And throttle while rolling backwards brakes to exactly zero before driving forwards.
  bool saw_zero = false;
  for (int i = 0; i < 200; ++i) {
    const double before = s.speed;
    s = step(s, kUp, p, kDt);
    if (before < 0.0) {
      ASSERT_LE(s.speed, 0.0);
    }
    saw_zero = saw_zero || s.speed == 0.0;
  }
  EXPECT_TRUE(saw_zero);
  EXPECT_GT(s.speed, 0.0);
}

TEST_P(EveryIntegrator, BothPedalsBrakeAndCoastingNeverFlipsTheSign) {
  const CarParams p = CarParams{};
  CarState s;
  s.speed = 30.0;
  for (int i = 0; i < 1000; ++i) {
    s = step(s, InputFrame{true, true, false, false}, p, kDt);
    ASSERT_GE(s.speed, 0.0);
  }
  EXPECT_EQ(s.speed, 0.0);
  s.speed = -3.0;
  for (int i = 0; i < 100000 && s.speed != 0.0; ++i) {
    s = step(s, kNone, p, kDt);
    ASSERT_LE(s.speed, 0.0);
  }
  EXPECT_EQ(s.speed, 0.0);
  const CarState rest = step(s, kNone, p, kDt);
  EXPECT_EQ(rest.speed, 0.0);
  EXPECT_EQ(rest.position, s.position);
}

TEST_P(EveryIntegrator, ReverseSpeedIsCapped) {
  for (const CarParams& p : {CarParams{}, frictionless()}) {
    CarState s;
    for (int i = 0; i < 120 * 30; ++i) {
      s = step(s, kDown, p, kDt);
      ASSERT_GE(s.speed, -p.max_reverse_speed);
    }
    if (p.drag == 0.0) {
      EXPECT_EQ(s.speed, -p.max_reverse_speed);
    }
  }
}

TEST_P(EveryIntegrator, HeadingStaysWrappedOverAMillionStepsOfCircling) {
  const CarParams p = CarParams{};
  CarState s;
  s.speed = 12.0;
  for (int i = 0; i < 1000000; ++i) {
    // Throttle now and then keeps the speed up against drag.
    s = step(s, (i % 4 == 0) ? InputFrame{true, false, true, false} : kLeft, p, kDt);
    ASSERT_GT(s.heading, -std::numbers::pi);
    ASSERT_LE(s.heading, std::numbers::pi);
    ASSERT_EQ(s.direction, unitFromRadians(s.heading));
  }
  EXPECT_NEAR(s.direction.norm(), 1.0, 1e-15);
  EXPECT_LT(s.position.norm(), 100.0);  // still circling near the start
}

TEST_P(EveryIntegrator, SteeringIsRateLimitedAndNarrowsWithSpeed) {
  const CarParams p = CarParams{};
  EXPECT_EQ(steeringLock(p, 0.0), p.max_steer);
  EXPECT_DOUBLE_EQ(steeringLock(p, p.lock_speed), 0.5 * p.max_steer);
  EXPECT_DOUBLE_EQ(steeringLock(p, -p.lock_speed), 0.5 * p.max_steer);
  CarState s;
  const double max_delta = p.steer_rate * kDt;
  auto run = [&](const InputFrame& in, int steps) {
    for (int i = 0; i < steps; ++i) {
      const double before = s.steer;
      s = step(s, in, p, kDt);
      ASSERT_LE(std::abs(s.steer - before), max_delta * (1.0 + 1e-12));
      ASSERT_LE(std::abs(s.steer), steeringLock(p, 0.0));
    }
  };
  run(kLeft, 1);
  EXPECT_DOUBLE_EQ(s.steer, max_delta);
  run(kLeft, 200);
  EXPECT_EQ(s.steer, p.max_steer);  // lands exactly on the lock
  run(kRight, 1);
  EXPECT_DOUBLE_EQ(s.steer, p.max_steer - max_delta);
  run(kRight, 200);
  EXPECT_EQ(s.steer, -p.max_steer);
  run(InputFrame{false, false, true, true}, 200);
  EXPECT_EQ(s.steer, 0.0);
  // At speed the target narrows: the wheel settles on the narrower lock.
  s.speed = p.lock_speed;
  CarParams cruise = p;
  cruise.drag = 0.0;
  cruise.rolling_resistance = 0.0;
  cruise.engine_brake = 0.0;
  cruise.grip = 1e9;  // the geometry alone
  for (int i = 0; i < 200; ++i) s = step(s, kLeft, cruise, kDt);
  EXPECT_DOUBLE_EQ(s.steer, 0.5 * p.max_steer);
}

TEST_P(EveryIntegrator, EngineBrakingStopsAtTheConstantDecelerationDistance) {
  // No drag: v' = -(engine_brake + rolling) until the stop, so d = v0^2 / (2 a).
  CarParams p = CarParams{};
  p.drag = 0.0;
  const double v0 = 50.0 / 3.6;
  const double a = p.engine_brake + p.rolling_resistance;
  CarState s;
  s.speed = v0;
  int steps = 0;
  while (s.speed > 0.0 && steps < 100000) {
    s = step(s, kNone, p, kDt);
    ++steps;
  }
  EXPECT_EQ(s.speed, 0.0);
  // First-order schemes are off by at most one step's travel.
  EXPECT_NEAR(s.position.x(), v0 * v0 / (2.0 * a), v0 * kDt);
  EXPECT_NEAR(steps * kDt, v0 / a, kDt);
}

TEST_P(EveryIntegrator, GripCapsTheTurnAtTheGripRadius) {
  // Constant speed (no resistance): the wheel settles on the grip lock and the car circles with
  // radius v^2 / grip, so the heading turns by grip / v per second.
  CarParams p = frictionless();
  const double v = 20.0;
  ASSERT_LT(gripLock(p, v), steeringLock(p, v));
  CarState s;
  s.speed = v;
  for (int i = 0; i < 240; ++i) s = step(s, kLeft, p, kDt);
  EXPECT_EQ(s.steer, gripLock(p, v));
  EXPECT_EQ(s.speed, v);
  const double radius = p.wheelbase / std::tan(s.steer);
  EXPECT_NEAR(radius, v * v / p.grip, 1e-9 * radius);
  const double h0 = s.heading;
  for (int i = 0; i < 60; ++i) s = step(s, kLeft, p, kDt);
  EXPECT_NEAR(wrapRadians(s.heading - h0), 0.5 * p.grip / v, 1e-12);
  EXPECT_EQ(s.slip, 0.0);
  // At parking speeds the steering geometry, not the grip, limits the lock.
  EXPECT_EQ(effectiveLock(p, 3.0, false), steeringLock(p, 3.0));
  EXPECT_EQ(effectiveLock(p, v, true), steeringLock(p, v));
}

TEST_P(EveryIntegrator, HandbrakeDeceleratesAtItsRate) {
  CarParams p = frictionless();
  CarState s;
  s.speed = 10.0;
  for (int i = 0; i < 120; ++i) s = step(s, InputFrame{true, false, false, false, true}, p, kDt);
  EXPECT_NEAR(s.speed, 10.0 - p.handbrake_decel, 1e-9);
  EXPECT_NEAR(s.position.x(), 10.0 - 0.5 * p.handbrake_decel, p.handbrake_decel * kDt);
  while (s.speed > 0.0) s = step(s, kHandbrake, p, kDt);
  EXPECT_EQ(s.speed, 0.0);
  // It holds the car at rest against the throttle.
  s = step(s, InputFrame{true, false, false, false, true}, p, kDt);
  EXPECT_EQ(s.speed, 0.0);
}

TEST_P(EveryIntegrator, HandbrakeTurnYawsWhileTheVelocityLags) {
  const CarParams p = CarParams{};
  CarState s;
  s.speed = 15.0;
  CarState plain = s;
  double slowest = s.speed;
  for (int i = 0; i < 60; ++i) {
    s = step(s, InputFrame{false, false, true, false, true}, p, kDt);
    plain = step(plain, kLeft, p, kDt);
    slowest = std::min(slowest, s.velocity().norm());
  }
  const Eigen::Vector2d v = s.velocity();
  const double course = std::atan2(v.y(), v.x());
  EXPECT_GT(s.heading, 2.0 * plain.heading);  // the rear swings round
  EXPECT_GT(s.heading, 0.5);
  // The velocity turns only by the rear grip: a = |v| dcourse/dt <= handbrake_grip * grip.
  EXPECT_GT(course, 0.0);
  EXPECT_LE(course, p.handbrake_grip * p.grip * 0.5 / slowest);
  EXPECT_LT(s.slip, -p.skid_slip);  // sliding outwards (to the right of the heading)
  // Released, the slip decays at the full grip rate.
  const double slip = s.slip;
  s = step(s, kNone, p, kDt);
  EXPECT_NEAR(s.slip, slip + p.grip * kDt, 1e-12);
}

TEST_P(EveryIntegrator, SlipMovesTheCarAndDecaysUnlessAgainstASurface) {
  const CarParams p = CarParams{};
  CarState s;
  s.slip = 3.0;
  s = step(s, kNone, p, kDt);
  EXPECT_EQ(s.position.x(), 0.0);
  EXPECT_DOUBLE_EQ(s.position.y(), 3.0 * kDt);
  EXPECT_DOUBLE_EQ(s.slip, 3.0 - p.grip * kDt);
  for (int i = 0; i < 60; ++i) s = step(s, kNone, p, kDt);
  EXPECT_EQ(s.slip, 0.0);
  EXPECT_NEAR(s.position.y(), 3.0 * 3.0 / (2.0 * p.grip), 3.0 * kDt);
  // Against a surface the decay stops where the velocity runs along it: here a wall at +y (normal
  // +y from the car) with the car moving at 4 m/s along a heading 10 degrees into it.
  CarState held;
  held.heading = 10.0 * std::numbers::pi / 180.0;
  held.direction = unitFromRadians(held.heading);
  held.speed = 4.0;
  held.surface_normal = {0.0, 1.0};
  const double along = -4.0 * std::tan(held.heading);  // velocity (4 / cos 10, 0)
  held.slip = along - 0.01;  // drifting off the wall: the decay would turn it back into it
  CarParams coast = p;
  coast.engine_brake = 0.0;
  coast.rolling_resistance = 0.0;
  coast.drag = 0.0;
  held = step(held, kNone, coast, kDt);
  EXPECT_DOUBLE_EQ(held.slip, along);
  EXPECT_NEAR(held.velocity().y(), 0.0, 1e-12);
}

TEST_P(EveryIntegrator, SpeedCapIsReachedAndHeld) {
  CarParams p = CarParams{};
  p.max_speed = 5.5;
  CarState s;
  double top = 0.0;
  for (int i = 0; i < 120 * 10; ++i) {
    s = step(s, kUp, p, kDt);
    ASSERT_LE(s.speed, p.max_speed);
    top = std::max(top, s.speed);
  }
  // Semi-implicit Euler applies the resistance after the capped command, so it stays a hair below.
  EXPECT_GT(top, p.max_speed - 0.01);
  EXPECT_GT(s.speed, p.max_speed - 0.01);
  // An initial speed above the cap is not clamped: the engine just stops pushing.
  CarState fast;
  fast.speed = 8.0;
  fast = step(fast, kUp, p, kDt);
  EXPECT_LT(fast.speed, 8.0);
  EXPECT_GT(fast.speed, 7.9);
}

// Held at either limit, the speed lands on it or within an ulp or two of it, on either side, and a
// turned or mirrored copy of the drive lands on another of those values. The step from each must
// be the step from the limit: before settledAtLimit, a start speed on the limit or past it turned
// the engine off for the step (a 2 mm/s dip every other frame, and about 3e-5 m of position).
TEST_P(EveryIntegrator, StepIsContinuousInTheStartSpeedAtEitherLimit) {
  CarParams p = CarParams{};
  p.max_speed = 5.5;
  for (const auto& [keys, limit] :
       {std::pair{kUp, p.max_speed}, std::pair{kDown, -p.max_reverse_speed}}) {
    CarState at;
    at.position = {12.5, -3.25};
    at.heading = 0.3;
    at.direction = unitFromRadians(at.heading);
    at.speed = limit;
    const CarState reference = step(at, keys, p, kDt);
    // The step from the limit keeps it (within the resistance that semi-implicit Euler applies
    // after its capped command).
    EXPECT_NEAR(reference.speed, limit, 1e-3 * std::abs(limit)) << "limit " << limit;
    double inside = limit, beyond = limit;
    for (int ulps = 1; ulps <= 3; ++ulps) {
      inside = std::nextafter(inside, 0.0);
      beyond = std::nextafter(beyond, 2.0 * limit);
      for (const double start : {inside, beyond}) {
        CarState s = at;
        s.speed = start;
        const CarState next = step(s, keys, p, kDt);
        EXPECT_LE((next.position - reference.position).norm(), 1e-12)
            << "limit " << limit << ", start " << start;
        EXPECT_LE(std::abs(next.speed - reference.speed), 1e-12)
            << "limit " << limit << ", start " << start;
      }
    }
  }
}

}  // namespace cardemo::testing
