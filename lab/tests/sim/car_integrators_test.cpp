// The lab's car integrators: the properties every integrator keeps (tests/sim's suite) and
// semi-implicit Euler's own closed forms.

#include "lab/sim/car_integrators.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/sim/car_integrator_properties.hpp"
#include "tests/sim/key_frames.hpp"

namespace cardemo {
namespace {

using testing::EveryIntegrator;
using testing::frictionless;
using testing::IntegratorCase;
using testing::kDown;
using testing::kDt;
using testing::kLeft;
using testing::kUp;

INSTANTIATE_TEST_SUITE_P(Car, EveryIntegrator,
                         ::testing::Values(IntegratorCase{"SemiImplicitEuler",
                                                          stepSemiImplicitEuler},
                                           IntegratorCase{"ExplicitEuler", stepExplicitEuler},
                                           IntegratorCase{"Rk4", stepRk4}),
                         testing::integratorName);

TEST(Car, SemiImplicitEulerUnderConstantAccelerationMatchesItsDiscreteClosedForm) {
  const CarParams p = frictionless();
  CarState s;
  s.speed = 2.0;
  const double v0 = s.speed, a = p.engine_accel;
  for (int n = 1; n <= 600; ++n) {
    s = integrateCar(s, kUp, p, kDt, stepSemiImplicitEuler);
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

TEST(Car, SemiImplicitEulerCirclesOnTheChordPolygonOfTheBicycleRadius) {
  CarParams p = frictionless();
  p.lock_speed = 1e12;  // no narrowing at 10 m/s
  p.grip = 1e9;         // and no grip limit
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
    s = integrateCar(s, kLeft, p, kDt, stepSemiImplicitEuler);
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

}  // namespace
}  // namespace cardemo
