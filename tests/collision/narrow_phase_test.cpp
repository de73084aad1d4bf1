#include "collision/narrow_phase.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "geometry/sat_obb2.hpp"

namespace cardemo {
namespace {

// One draw a statement, so GCC and Clang build the same boxes (argument order is unspecified).
Obb2 randomBox(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> pos(-6.0, 6.0), deg(-180.0, 180.0), size(0.5, 5.0);
  const Eigen::Vector2d center{pos(rng), pos(rng)};
  const double heading = deg(rng);
  const double length = size(rng);
  const double width = size(rng);
  return Obb2::fromDegrees(center, heading, length, width);
}

TEST(NarrowPhase, BoxDispatchMatchesCollideObb2) {
  std::mt19937_64 rng(11);
  for (int i = 0; i < 2000; ++i) {
    const Obb2 a = randomBox(rng);
    const Obb2 b = randomBox(rng);
    const SatResult2 want = collideObb2(a, b);
    const SatResult2 got = collidePlayer(a, StaticShape{b});
    ASSERT_EQ(got.hit, want.hit);
    ASSERT_EQ(got.separation, want.separation);
    ASSERT_EQ(got.normal, want.normal);
  }
}

TEST(NarrowPhase, PolygonDispatchAgreesWithTheSameBoxAsAnObb) {
  std::mt19937_64 rng(12);
  for (int i = 0; i < 2000; ++i) {
    const Obb2 a = randomBox(rng);
    const Obb2 b = randomBox(rng);
    const SatResult2 box = collidePlayer(a, StaticShape{b});
    const SatResult2 poly = collidePlayer(a, StaticShape{ConvexPolygon::fromObb(b)});
    ASSERT_NEAR(poly.separation, box.separation, 1e-9) << "case " << i;
    if (std::abs(box.separation) > 1e-6) {
      ASSERT_EQ(poly.hit, box.hit) << "case " << i;
    }
  }
}

TEST(NarrowPhase, SeparationAlongAnAxisMatchesTheCornersAndTheSat) {
  // Brute-force twin: the gap between the corners' projections; and along SAT's own normal it is
  // SAT's separation (for a box, and for the same box as a polygon).
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> deg(-180.0, 180.0);
  for (int i = 0; i < 2000; ++i) {
    const Obb2 a = randomBox(rng);
    const Obb2 b = randomBox(rng);
    const double angle = deg(rng) * 3.14159265358979323846 / 180.0;
    const Eigen::Vector2d axis(std::cos(angle), std::sin(angle));
    double a_max = -1e300, b_min = 1e300;
    for (const Eigen::Vector2d& c : a.corners()) a_max = std::max(a_max, c.dot(axis));
    for (const Eigen::Vector2d& c : b.corners()) b_min = std::min(b_min, c.dot(axis));
    ASSERT_NEAR(separationAlong(a, StaticShape{b}, axis), b_min - a_max, 1e-12) << "case " << i;
    ASSERT_NEAR(separationAlong(a, StaticShape{ConvexPolygon::fromObb(b)}, axis), b_min - a_max,
                1e-12)
        << "case " << i;
    const SatResult2 sat = collidePlayer(a, StaticShape{b});
    ASSERT_NEAR(separationAlong(a, StaticShape{b}, sat.normal), sat.separation, 1e-12)
        << "case " << i;
  }
}

TEST(NarrowPhase, BoundsOfBothShapes) {
  const Obb2 b = Obb2::fromDegrees({1.0, 2.0}, 90.0, 4.0, 2.0);
  const Aabb2 box = boundsOf(StaticShape{b});
  EXPECT_EQ(box.min, Eigen::Vector2d(0.0, 0.0));
  EXPECT_EQ(box.max, Eigen::Vector2d(2.0, 4.0));
  const Aabb2 poly = boundsOf(StaticShape{ConvexPolygon::fromObb(b)});
  EXPECT_NEAR((poly.min - box.min).norm(), 0.0, 1e-12);
  EXPECT_NEAR((poly.max - box.max).norm(), 0.0, 1e-12);
}

}  // namespace
}  // namespace cardemo
