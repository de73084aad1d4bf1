// The closed forms themselves, checked against the ODE they claim to solve (central differences),
// their limits and special cases, and against RK4 run at a very fine step.
#include "lab/kernels/car_closed_form.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "lab/sim/car_integrators.hpp"
#include "lab/tests/sim/closed_form_runs.hpp"

namespace cardemo {
namespace {

// Central difference of f at t with step h: error O(h^2 f''').
template <typename F>
double derivative(F f, double t, double h = 1e-4) {
  return (f(t + h) - f(t - h)) / (2.0 * h);
}

TEST(ClosedForm, UnderThrottleSolvesTheOde) {
  struct Case {
    double v0, net, drag;
  };
  // Below, at and above the terminal speed sqrt(net/drag); weak and strong drag; from rest.
  for (const Case c : {Case{0.0, 3.85, 0.0016}, Case{2.0, 3.85, 0.05}, Case{30.0, 3.85, 0.05},
                       Case{std::sqrt(3.85 / 0.05), 3.85, 0.05}, Case{5.0, 1.0, 1e-9}}) {
    SCOPED_TRACE(testing::Message() << "v0 " << c.v0 << " drag " << c.drag);
    const SpeedAndDistance at0 = underThrottle(c.v0, c.net, c.drag, 0.0);
    EXPECT_NEAR(at0.speed, c.v0, 1e-12 * (1.0 + c.v0));
    EXPECT_EQ(at0.distance, 0.0);
    for (const double t : {0.01, 0.3, 1.0, 4.0, 20.0}) {
      const auto speed = [&](double u) { return underThrottle(c.v0, c.net, c.drag, u).speed; };
      const auto distance = [&](double u) {
        return underThrottle(c.v0, c.net, c.drag, u).distance;
      };
      const double v = speed(t);
      EXPECT_NEAR(derivative(distance, t), v, 1e-6 * (1.0 + v)) << "t " << t;
      EXPECT_NEAR(derivative(speed, t), c.net - c.drag * v * v, 1e-6) << "t " << t;
    }
  }
}

TEST(ClosedForm, UnderThrottleLimits) {
  // No drag: uniform acceleration exactly.
  const SpeedAndDistance linear = underThrottle(3.0, 2.0, 0.0, 5.0);
  EXPECT_EQ(linear.speed, 13.0);
  EXPECT_EQ(linear.distance, 40.0);
  // At the terminal speed the car cruises.
  const double terminal = std::sqrt(4.0 / 0.01);
  const SpeedAndDistance cruise = underThrottle(terminal, 4.0, 0.01, 7.0);
  EXPECT_NEAR(cruise.speed, terminal, 1e-12 * terminal);
  EXPECT_NEAR(cruise.distance, terminal * 7.0, 1e-10 * terminal * 7.0);
  // Long after the start, from below or above, the speed is terminal and the distance grows at it.
  for (const double v0 : {0.0, 100.0}) {
    const SpeedAndDistance a = underThrottle(v0, 4.0, 0.01, 300.0);
    const SpeedAndDistance b = underThrottle(v0, 4.0, 0.01, 301.0);
    EXPECT_NEAR(a.speed, terminal, 1e-9);
    EXPECT_NEAR(b.distance - a.distance, terminal, 1e-9);
  }
  // The two ways of evaluating ln(cosh x + r sinh x) meet at x = 20.
  const double k = std::sqrt(4.0 * 0.01);
  const double below = underThrottle(5.0, 4.0, 0.01, std::nextafter(20.0 / k, 0.0)).distance;
  const double above = underThrottle(5.0, 4.0, 0.01, 20.0 / k).distance;
  EXPECT_NEAR(below, above, 1e-12 * above);
  // Tiny drag approaches the drag-free answer.
  const SpeedAndDistance tiny = underThrottle(3.0, 2.0, 1e-12, 5.0);
  EXPECT_NEAR(tiny.speed, 13.0, 1e-8);
  EXPECT_NEAR(tiny.distance, 40.0, 1e-7);
}

TEST(ClosedForm, CoastingSolvesTheOdeAndStops) {
  struct Case {
    double v0, rolling, drag;
  };
  for (const Case c : {Case{30.0, 0.15, 0.0016}, Case{10.0, 0.15, 0.05}, Case{10.0, 0.0, 0.05},
                       Case{10.0, 0.15, 0.0}, Case{10.0, 0.0, 0.0}}) {
    SCOPED_TRACE(testing::Message()
                 << "v0 " << c.v0 << " rolling " << c.rolling << " drag " << c.drag);
    const auto speed = [&](double u) { return coasting(c.v0, c.rolling, c.drag, u).speed; };
    const auto distance = [&](double u) { return coasting(c.v0, c.rolling, c.drag, u).distance; };
    EXPECT_EQ(speed(0.0), c.v0);
    EXPECT_EQ(distance(0.0), 0.0);
    for (const double t : {0.01, 0.5, 2.0, 5.0}) {
      const double v = speed(t);
      ASSERT_GT(v, 0.0);
      EXPECT_NEAR(derivative(distance, t), v, 1e-6 * (1.0 + v)) << "t " << t;
      EXPECT_NEAR(derivative(speed, t), -(c.rolling + c.drag * v * v), 1e-6) << "t " << t;
    }
  }
  // With rolling resistance the car stops at t* = atan(q) / k and stays where it stopped.
  const double w = std::sqrt(0.15 / 0.05), k = std::sqrt(0.15 * 0.05);
  const double stop = std::atan(10.0 / w) / k;
  EXPECT_GT(coasting(10.0, 0.15, 0.05, 0.999 * stop).speed, 0.0);
  EXPECT_EQ(coasting(10.0, 0.15, 0.05, stop).speed, 0.0);
  const double parked = coasting(10.0, 0.15, 0.05, stop).distance;
  EXPECT_EQ(coasting(10.0, 0.15, 0.05, 10.0 * stop).distance, parked);
  // The stopping distance by energy-like integration: int v dv / (r + c v^2) = ln(1 + c v0^2 / r)
  // / (2c).
  EXPECT_NEAR(parked, std::log1p(0.05 * 100.0 / 0.15) / (2.0 * 0.05), 1e-12 * parked);
  // Without drag: v0^2 / (2 r).
  EXPECT_NEAR(coasting(10.0, 0.15, 0.0, 1000.0).distance, 100.0 / 0.3, 1e-12);
}

TEST(ClosedForm, AlongArcStaysOnTheBicycleCircle) {
  CarState s0;
  s0.position = {3.0, -2.0};
  s0.heading = 0.7;
  s0.direction = {std::cos(0.7), std::sin(0.7)};
  for (const double k : {0.2, -0.05, 1e-7}) {
    const Eigen::Vector2d left(-s0.direction.y(), s0.direction.x());
    const Eigen::Vector2d centre = s0.position + left / k;
    for (const double s : {-3.0, 0.5, 10.0, 100.0}) {
      SCOPED_TRACE(testing::Message() << "k " << k << " s " << s);
      const CarState e = alongArc(s0, k, s);
      EXPECT_NEAR(e.heading, 0.7 + k * s, 1e-15);
      EXPECT_NEAR((e.direction - Eigen::Vector2d(std::cos(e.heading), std::sin(e.heading))).norm(),
                  0.0, 1e-15);
      // On the circle of radius 1/|k| (relative check: the radius is 1e7 m for k = 1e-7).
      EXPECT_NEAR((e.position - centre).norm(), 1.0 / std::abs(k), 1e-9 * (1.0 / std::abs(k)));
      // Moving along the heading: d position / d s = direction.
      const Eigen::Vector2d slope =
          (alongArc(s0, k, s + 1e-5).position - alongArc(s0, k, s - 1e-5).position) / 2e-5;
      EXPECT_NEAR((slope - e.direction).norm(), 0.0, 1e-7);
      if (std::abs(k * s) > 0.1) {
        // The textbook form p0 + (sin h1 - sin h0, cos h0 - cos h1) / k (no cancellation here).
        const double h0 = s0.heading, h1 = h0 + k * s;
        const Eigen::Vector2d textbook =
            s0.position +
            Eigen::Vector2d(std::sin(h1) - std::sin(h0), std::cos(h0) - std::cos(h1)) / k;
        EXPECT_NEAR((e.position - textbook).norm(), 0.0, 1e-12);
      }
    }
  }
  // Zero curvature: a straight line along the heading.
  const CarState line = alongArc(s0, 0.0, 5.0);
  EXPECT_NEAR((line.position - (s0.position + 5.0 * s0.direction)).norm(), 0.0, 1e-15);
  // A full turn comes back to the start.
  const double k = 0.25;
  EXPECT_NEAR((alongArc(s0, k, 2.0 * std::numbers::pi / k).position - s0.position).norm(), 0.0,
              1e-13);
}

// Independent of the closed forms' derivation: a very fine RK4 run lands on them.
TEST(ClosedForm, FineRk4RunsLandOnEveryReference) {
  for (const test::ClosedFormRun& run :
       {test::throttleRun(), test::coastRun(), test::circleRun(), test::acceleratingTurnRun()}) {
    const test::RunError e = test::integrate(run, stepRk4, 4000, 2.0);
    EXPECT_LT(e.max_error, 1e-10) << run.name;
  }
}

}  // namespace
}  // namespace cardemo
