#include "sim/car.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "geometry/angle.hpp"

namespace cardemo {
namespace {

constexpr double kDt = 1.0 / 120.0;
constexpr InputFrame kNone{};
constexpr InputFrame kUp{true, false, false, false};
constexpr InputFrame kDown{false, true, false, false};
constexpr InputFrame kLeft{false, false, true, false};
constexpr InputFrame kRight{false, false, false, true};

CarParams frictionless(CarIntegrator integrator = CarIntegrator::kSemiImplicitEuler) {
  CarParams p;
  p.drag = 0.0;
  p.rolling_resistance = 0.0;
  p.integrator = integrator;
  return p;
}

CarParams withIntegrator(CarIntegrator integrator) {
  CarParams p;
  p.integrator = integrator;
  return p;
}

// Properties every integrator must keep (the speed law's stops and caps, the steering, the exact
// axis directions, the heading wrap), run once per scheme.
class EveryIntegrator : public ::testing::TestWithParam<CarIntegrator> {};

INSTANTIATE_TEST_SUITE_P(Car, EveryIntegrator,
                         ::testing::Values(CarIntegrator::kSemiImplicitEuler,
                                           CarIntegrator::kExplicitEuler, CarIntegrator::kRk4,
                                           CarIntegrator::kArcRk4),
                         [](const ::testing::TestParamInfo<CarIntegrator>& info) {
                           switch (info.param) {
                             case CarIntegrator::kSemiImplicitEuler:
                               return std::string("SemiImplicitEuler");
                             case CarIntegrator::kExplicitEuler:
                               return std::string("ExplicitEuler");
                             case CarIntegrator::kRk4:
                               return std::string("Rk4");
                             case CarIntegrator::kArcRk4:
                               return std::string("ArcRk4");
                           }
                           return std::string("Unknown");
                         });

TEST(Car, SemiImplicitEulerUnderConstantAccelerationMatchesItsDiscreteClosedForm) {
  const CarParams p = frictionless(CarIntegrator::kSemiImplicitEuler);
  CarState s;
  s.speed = 2.0;
  const double v0 = s.speed, a = p.engine_accel;
  for (int n = 1; n <= 600; ++n) {
    s = integrateCar(s, kUp, p, kDt);
    // Semi-implicit Euler: v_k = v0 + k a dt and x_n = sum_k v_k dt = v0 t + a t^2 / 2 + a t dt
    // / 2.
    const double t = n * kDt;
    const double discrete = v0 * t + 0.5 * a * kDt * kDt * n * (n + 1.0);
    ASSERT_NEAR(s.position.x(), discrete, 1e-11 * (1.0 + discrete)) << "step " << n;
    ASSERT_NEAR(s.position.x() - (v0 * t + 0.5 * a * t * t), 0.5 * a * t * kDt, 1e-10)
        << "step " << n;
    ASSERT_NEAR(s.speed, v0 + a * t, 1e-12);
    ASSERT_EQ(s.position.y(), 0.0);
    ASSERT_EQ(s.direction, Eigen::Vector2d::UnitX());
  }
}

TEST_P(EveryIntegrator, ExactAxisDirectionSurvivesStraightDriving) {
  const CarParams p = withIntegrator(GetParam());
  CarState s;
  s.heading = wrapRadians(90.0 * std::numbers::pi / 180.0);
  s.direction = unitFromDegrees(90.0);
  ASSERT_EQ(s.direction, Eigen::Vector2d(0.0, 1.0));
  for (int i = 0; i < 2000; ++i) s = integrateCar(s, i < 1000 ? kUp : kDown, p, kDt);
  EXPECT_EQ(s.direction, Eigen::Vector2d(0.0, 1.0));
  EXPECT_EQ(s.position.x(), 0.0);
  EXPECT_GT(s.position.y(), 10.0);
}

TEST(Car, SemiImplicitEulerCirclesOnTheChordPolygonOfTheBicycleRadius) {
  CarParams p = frictionless(CarIntegrator::kSemiImplicitEuler);
  p.lock_speed = 1e12;  // no narrowing at 10 m/s
  p.max_steer = 0.3;
  CarState s;
  s.position = {3.0, -2.0};
  s.heading = 0.7;
  s.direction = unitFromRadians(s.heading);
  s.speed = 10.0;
  s.steer = 0.3;  // already at its target
  const double radius =
      p.wheelbase / std::tan(p.max_steer);  // Rajamani sec. 2.2, R = L / tan(delta)
  const double omega = s.speed / radius;
  // The semi-implicit steps are chords of length v dt turning by omega dt: their vertices lie on a
  // circle of radius v dt / (2 sin(omega dt / 2)) = R (1 - O(dt^2)) whose centre is fixed.
  const double h = omega * kDt;
  const double r = s.speed * kDt / (2.0 * std::sin(0.5 * h));
  const Eigen::Vector2d centre =
      s.position + r * unitFromRadians(s.heading + 0.5 * h + 0.5 * std::numbers::pi);
  EXPECT_NEAR(r, radius, 1e-4 * radius);
  const Eigen::Vector2d start = s.position;
  double turned = 0.0;
  int steps = 0;
  while (turned < 2.0 * std::numbers::pi) {
    const double before = s.heading;
    s = integrateCar(s, kLeft, p, kDt);
    ASSERT_EQ(s.steer, 0.3);
    turned += wrapRadians(s.heading - before);
    ++steps;
    ASSERT_NEAR((s.position - centre).norm(), r, 1e-9) << "step " << steps;
    ASSERT_NEAR((s.position - centre).norm(), radius, 1e-3) << "step " << steps;
  }
  const double lap_time = 2.0 * std::numbers::pi * radius / s.speed;
  EXPECT_NEAR(steps * kDt, lap_time, kDt);
  EXPECT_LT((s.position - start).norm(), s.speed * kDt);
}

TEST_P(EveryIntegrator, BrakingStopsExactlyAtZeroThenReverses) {
  const CarParams p = withIntegrator(GetParam());
  CarState s;
  s.speed = 5.0;
  int stopped_at = -1;
  for (int i = 0; i < 200; ++i) {
    const double before = s.speed;
    s = integrateCar(s, kDown, p, kDt);
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
    s = integrateCar(s, kUp, p, kDt);
    if (before < 0.0) {
      ASSERT_LE(s.speed, 0.0);
    }
    saw_zero = saw_zero || s.speed == 0.0;
  }
  EXPECT_TRUE(saw_zero);
  EXPECT_GT(s.speed, 0.0);
}

TEST_P(EveryIntegrator, BothPedalsBrakeAndCoastingNeverFlipsTheSign) {
  const CarParams p = withIntegrator(GetParam());
  CarState s;
  s.speed = 30.0;
  for (int i = 0; i < 1000; ++i) {
    s = integrateCar(s, InputFrame{true, true, false, false}, p, kDt);
    ASSERT_GE(s.speed, 0.0);
  }
  EXPECT_EQ(s.speed, 0.0);
  s.speed = -3.0;
  for (int i = 0; i < 100000 && s.speed != 0.0; ++i) {
    s = integrateCar(s, kNone, p, kDt);
    ASSERT_LE(s.speed, 0.0);
  }
  EXPECT_EQ(s.speed, 0.0);
  const CarState rest = integrateCar(s, kNone, p, kDt);
  EXPECT_EQ(rest.speed, 0.0);
  EXPECT_EQ(rest.position, s.position);
}

TEST_P(EveryIntegrator, ReverseSpeedIsCapped) {
  for (const CarParams& p : {withIntegrator(GetParam()), frictionless(GetParam())}) {
    CarState s;
    for (int i = 0; i < 120 * 30; ++i) {
      s = integrateCar(s, kDown, p, kDt);
      ASSERT_GE(s.speed, -p.max_reverse_speed);
    }
    if (p.drag == 0.0) {
      EXPECT_EQ(s.speed, -p.max_reverse_speed);
    }
  }
}

TEST_P(EveryIntegrator, HeadingStaysWrappedOverAMillionStepsOfCircling) {
  const CarParams p = withIntegrator(GetParam());
  CarState s;
  s.speed = 12.0;
  for (int i = 0; i < 1000000; ++i) {
    // Throttle now and then keeps the speed up against drag.
    s = integrateCar(s, (i % 4 == 0) ? InputFrame{true, false, true, false} : kLeft, p, kDt);
    ASSERT_GT(s.heading, -std::numbers::pi);
    ASSERT_LE(s.heading, std::numbers::pi);
    ASSERT_EQ(s.direction, unitFromRadians(s.heading));
  }
  EXPECT_NEAR(s.direction.norm(), 1.0, 1e-15);
  EXPECT_LT(s.position.norm(), 100.0);  // still circling near the start
}

TEST_P(EveryIntegrator, SteeringIsRateLimitedAndNarrowsWithSpeed) {
  const CarParams p = withIntegrator(GetParam());
  EXPECT_EQ(steeringLock(p, 0.0), p.max_steer);
  EXPECT_DOUBLE_EQ(steeringLock(p, p.lock_speed), 0.5 * p.max_steer);
  EXPECT_DOUBLE_EQ(steeringLock(p, -p.lock_speed), 0.5 * p.max_steer);
  CarState s;
  const double max_delta = p.steer_rate * kDt;
  auto run = [&](const InputFrame& in, int steps) {
    for (int i = 0; i < steps; ++i) {
      const double before = s.steer;
      s = integrateCar(s, in, p, kDt);
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
  for (int i = 0; i < 200; ++i) s = integrateCar(s, kLeft, cruise, kDt);
  EXPECT_DOUBLE_EQ(s.steer, 0.5 * p.max_steer);
}

TEST(Car, BoxFollowsTheState) {
  CarParams p;
  CarState s;
  s.position = {1.0, 2.0};
  s.direction = unitFromDegrees(90.0);
  const Obb2 b = carBox(s, p);
  EXPECT_EQ(b.center, s.position);
  EXPECT_EQ(b.axis, s.direction);
  EXPECT_EQ(b.half, Eigen::Vector2d(2.25, 0.9));
}

}  // namespace
}  // namespace cardemo
