#include "sim/car.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

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

// The car's own face against a surface: the contact normal is its heading's axis to a few ulps,
// and which side of it rounding puts the normal must not matter (a rotated scene rounds the other
// way). Seeded headings; the normal turned by -2..+2 ulps-sized angles all give the same slide.
TEST(Car, SlideAgainstTheCarsOwnFaceDoesNotDependOnRounding) {
  CarParams p;
  std::uint64_t seed = 0x51de;
  for (int k = 0; k < 200; ++k) {
    seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
    const double heading = static_cast<double>(seed >> 11) * 0x1p-53 * 2.0 * std::numbers::pi;
    for (const double speed : {0.0, 0.02, -0.02}) {
      CarState s;
      s.heading = heading;
      s.direction = {std::cos(heading), std::sin(heading)};
      s.speed = speed;
      s.slip = (k % 2 == 0 ? 1.0 : -1.0) * 0.00112;
      std::vector<CarState> out;
      for (const double turn : {-4e-16, -1e-16, 0.0, 1e-16, 4e-16}) {
        for (const double side : {1.0, -1.0}) {
          CarState t = s;
          t.surface_normal =
              side * Eigen::Vector2d(std::cos(heading + turn), std::sin(heading + turn));
          out.push_back(slideCar(t, s, false, p, kDt));
        }
      }
      for (const CarState& o : out) {
        EXPECT_EQ(o.slip, out.front().slip) << "heading " << heading << " speed " << speed;
        EXPECT_EQ(o.position, out.front().position);
      }
      // Nothing holds the slip there: it decays as in the open.
      EXPECT_EQ(std::abs(out.front().slip), 0.0) << "heading " << heading << " speed " << speed;
    }
  }
}

}  // namespace
}  // namespace cardemo
