// The angle family: wrapRadians and wrapDegrees against exactly built cases, the degree
// conversions, and degreesOf at its edges.

#include "geometry/angle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

namespace cardemo {
namespace {

// x = r + 360 k is exact when r is a multiple of 2^-20 and |x| < 2^30: wrapDegrees must give r.
TEST(AngleWrap, DegreesComeBackToTheirRepresentative) {
  std::mt19937_64 rng(360);
  std::uniform_int_distribution<std::int64_t> fraction(-(180ll << 20) + 1, 180ll << 20);
  std::uniform_int_distribution<int> turns(-2000, 2000);
  for (int n = 0; n < 20000; ++n) {
    const double r = std::ldexp(static_cast<double>(fraction(rng)), -20);
    const double x = r + 360.0 * turns(rng);
    ASSERT_EQ(wrapDegrees(x), r) << x;
  }
  EXPECT_EQ(wrapDegrees(180.0), 180.0);
  EXPECT_EQ(wrapDegrees(-180.0), 180.0);
  EXPECT_EQ(wrapDegrees(540.0), 180.0);
  EXPECT_EQ(wrapDegrees(-540.0), 180.0);
  EXPECT_EQ(wrapDegrees(360.0), 0.0);
  EXPECT_EQ(wrapDegrees(-0.0), 0.0);
  EXPECT_TRUE(std::isnan(wrapDegrees(std::numeric_limits<double>::infinity())));
}

TEST(AngleWrap, RadiansStayInTheHalfOpenRange) {
  constexpr double kPiValue = std::numbers::pi;
  EXPECT_EQ(wrapRadians(kPiValue), kPiValue);
  EXPECT_EQ(wrapRadians(-kPiValue), kPiValue);
  EXPECT_EQ(wrapRadians(3.0 * kPiValue), kPiValue);
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> any(-1e4, 1e4);
  for (int n = 0; n < 20000; ++n) {
    const double x = any(rng);
    const double w = wrapRadians(x);
    ASSERT_TRUE(w > -kPiValue && w <= kPiValue) << x;
    // The same direction: x - w is a whole number of turns (to the rounding of 2 pi's multiple).
    const double turns = (x - w) / (2.0 * kPiValue);
    ASSERT_NEAR(turns, std::round(turns), 1e-9) << x;
  }
}

// The absolute turn between two wrapped headings, as World::moveContinuous takes it, equals the
// fold it replaced bit for bit (a change here would move the golden hashes).
TEST(AngleWrap, TheTurnBetweenWrappedHeadingsMatchesTheOldFold) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> heading(-std::numbers::pi, std::numbers::pi);
  for (int n = 0; n < 100000; ++n) {
    const double a = wrapRadians(heading(rng));
    const double b = n % 7 == 0 ? -a : wrapRadians(heading(rng));
    double fold = std::abs(a - b);
    if (fold > std::numbers::pi) fold = 2.0 * std::numbers::pi - fold;
    ASSERT_EQ(std::abs(wrapRadians(a - b)), fold) << a << " " << b;
  }
}

TEST(AngleConversions, UseTheOneRoundedFactor) {
  EXPECT_EQ(degreesFromRadians(std::numbers::pi), 180.0);
  EXPECT_EQ(radiansFromDegrees(180.0), std::numbers::pi);
  EXPECT_EQ(radiansFromDegrees(90.0), 90.0 * (std::numbers::pi / 180.0));
  EXPECT_EQ(degreesFromRadians(0.25), 0.25 * (180.0 / std::numbers::pi));
  static_assert(degreesFromRadians(0.0) == 0.0);
}

TEST(AngleConversions, DegreesOfADirectionLieInTheHalfOpenRange) {
  EXPECT_EQ(degreesOf({-1.0, 0.0}), 180.0);
  EXPECT_EQ(degreesOf({-1.0, -0.0}), 180.0) << "atan2 gives -pi here";
  EXPECT_EQ(degreesOf({0.0, 1.0}), 90.0);
  EXPECT_EQ(degreesOf({0.0, -1.0}), -90.0);
  EXPECT_EQ(degreesOf({1.0, 0.0}), 0.0);
}

}  // namespace
}  // namespace cardemo
