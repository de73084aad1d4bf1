// Convergence order of each integrator against the closed forms: as hz doubles, the position error
// must shrink by 2 (first order) or 16 (fourth order); the exact-arc scheme is exact on a circle.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "lab/sim/car_integrators.hpp"
#include "lab/tests/sim/closed_form_runs.hpp"

namespace cardemo {
namespace {

constexpr double kSeconds = 2.0;

struct Expectation {
  CarStepScheme integrator;  // null: the game's exact-arc RK4
  const char* name;
  int order;
};

const Expectation kSchemes[] = {
    {stepSemiImplicitEuler, "semi-implicit Euler", 1},
    {stepExplicitEuler, "explicit Euler", 1},
    {stepRk4, "RK4", 4},
    {nullptr, "arc + RK4", 4},
};

std::vector<test::ClosedFormRun> allRuns() {
  return {test::throttleRun(), test::coastRun(), test::circleRun(), test::acceleratingTurnRun()};
}

// Final position errors at 20, 40, 80 and 160 Hz over kSeconds.
std::vector<double> finalErrors(const test::ClosedFormRun& run, CarStepScheme integrator) {
  std::vector<double> errors;
  for (const int hz : {20, 40, 80, 160}) {
    errors.push_back(test::integrate(run, integrator, hz, kSeconds).final_error);
  }
  return errors;
}

TEST(IntegratorOrder, ErrorRatioAsHzDoublesMatchesTheOrder) {
  for (const test::ClosedFormRun& run : allRuns()) {
    for (const Expectation& scheme : kSchemes) {
      if (run.name == "circle" && scheme.integrator == nullptr) continue;  // exact
      SCOPED_TRACE(testing::Message() << run.name << ", " << scheme.name);
      const std::vector<double> e = finalErrors(run, scheme.integrator);
      // Far above rounding (the finest RK4 error is ~1e-12 m on positions of ~20 m).
      ASSERT_GT(e.back(), 5e-13);
      // The first doubling may still be outside the asymptotic range for RK4; the last two not.
      const double expected = std::pow(2.0, scheme.order);
      for (std::size_t i = scheme.order == 1 ? 1 : 2; i < e.size(); ++i) {
        EXPECT_GT(e[i - 1] / e[i], 0.85 * expected) << "doubling " << i;
        EXPECT_LT(e[i - 1] / e[i], 1.15 * expected) << "doubling " << i;
      }
    }
  }
}

TEST(IntegratorOrder, ExactArcIsExactOnACircleAndBeatsRk4WhenTurning) {
  const test::ClosedFormRun circle = test::circleRun();
  for (const int hz : {10, 20, 40, 80, 160}) {
    EXPECT_LT(test::integrate(circle, nullptr, hz, kSeconds).max_error, 1e-11) << hz << " Hz";
  }
  // Turning while accelerating, the arc is exact in the geometry and only the speed law's RK4
  // error remains, so it is well below full RK4 at every step.
  const test::ClosedFormRun turn = test::acceleratingTurnRun();
  const std::vector<double> arc = finalErrors(turn, nullptr);
  const std::vector<double> rk4 = finalErrors(turn, stepRk4);
  for (std::size_t i = 0; i < arc.size(); ++i) EXPECT_LT(arc[i], 0.5 * rk4[i]) << "index " << i;
}

TEST(IntegratorOrder, StraightRunsMoveOnlyAlongTheHeading) {
  // Explicit Euler, RK4 and the arc keep the speed law's distance on the start heading exactly,
  // whatever the speed does (the heading never moves with the wheel straight).
  for (const test::ClosedFormRun& run : {test::throttleRun(), test::coastRun()}) {
    for (const Expectation& scheme : kSchemes) {
      CarParams p = run.params;
      CarState s = run.start;
      for (int n = 0; n < 240; ++n)
        s = integrateCar(s, run.input, p, 1.0 / 120.0, scheme.integrator);
      EXPECT_EQ(s.heading, run.start.heading) << run.name << ", " << scheme.name;
      const Eigen::Vector2d moved = s.position - run.start.position;
      EXPECT_NEAR(moved.x() * run.start.direction.y() - moved.y() * run.start.direction.x(), 0.0,
                  1e-13)
          << run.name << ", " << scheme.name;
    }
  }
}

TEST(IntegratorOrder, BrakingStopsAtTheStoppingDistance) {
  // Frictionless braking from v0 stops after v0^2 / (2 b). The step in which the car stops holds
  // a kink in the speed; the RK4 stages are kept from passing zero, so the continuous schemes stay
  // within b dt^2 of it, the Euler schemes within their first-order v0 dt.
  CarParams p;
  p.drag = 0.0;
  p.rolling_resistance = 0.0;
  const double v0 = 20.0, dt = 1.0 / 120.0;
  const double exact = v0 * v0 / (2.0 * p.brake_decel);
  for (const Expectation& scheme : kSchemes) {
    CarState s;
    s.speed = v0;
    int steps = 0;
    while (s.speed > 0.0 && steps < 10000) {
      s = integrateCar(s, InputFrame{false, true, false, false}, p, dt, scheme.integrator);
      ++steps;
    }
    ASSERT_EQ(s.speed, 0.0) << scheme.name;
    const double bound = scheme.order == 4 ? p.brake_decel * dt * dt : v0 * dt;
    EXPECT_NEAR(s.position.x(), exact, bound) << scheme.name;
  }
}

}  // namespace
}  // namespace cardemo
