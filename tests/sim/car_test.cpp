#include "sim/car.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "car_integrator_properties.hpp"
#include "geometry/angle.hpp"
#include "key_frames.hpp"

namespace cardemo {
namespace {

using testing::kDown;
using testing::kHandbrake;
using testing::kLeft;
using testing::kNone;
using testing::kRight;
using testing::kUp;

using testing::EveryIntegrator;
using testing::frictionless;
using testing::IntegratorCase;
using testing::kDt;

// The game's integrator (exact-arc RK4); lab/tests/sim runs the same suite on the others.
INSTANTIATE_TEST_SUITE_P(Car, EveryIntegrator, ::testing::Values(IntegratorCase{"ArcRk4", nullptr}),
                         testing::integratorName);

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

// steerTarget is the wheel's goal integrateCar steers to; integrateCarToward with it is
// integrateCar.
TEST(Car, IntegrateCarTowardItsSteerTargetIsIntegrateCar) {
  const CarParams p;
  CarState s;
  s.speed = 15.0;
  for (const InputFrame in :
       {InputFrame{true, false, true, false}, InputFrame{false, false, false, true},
        InputFrame{false, false, true, true}, InputFrame{false, false, true, false, true}}) {
    const double target = steerTarget(p, s.speed, in);
    if (in.left == in.right) {
      EXPECT_EQ(target, 0.0);
    } else {
      EXPECT_EQ(std::abs(target), effectiveLock(p, s.speed, in.handbrake));
      EXPECT_EQ(target > 0.0, in.left);
    }
    const CarState a = integrateCar(s, in, p, kDt);
    const CarState b = integrateCarToward(s, in, p, kDt, target);
    EXPECT_EQ(a.steer, b.steer);
    EXPECT_EQ(a.heading, b.heading);
    EXPECT_EQ(a.position, b.position);
    EXPECT_EQ(a.speed, b.speed);
  }
}

}  // namespace
}  // namespace cardemo
