// The swept SAT (sweep_obb2, sweep_polygon) against the exact GMP oracle (exact_sweep): named cases
// for the oracle itself, then >= 100,000 seeded random cases per class.
//
// Bound asserted: with eps = kSweepTolerance (1e-6 m), the verdict is exact unless the oracle's
// verdict changes when A's projections are widened or narrowed by eps (borderline), and when both
// hit, |toi - toi*| * c <= eps, where c is the smaller of the two entry axes' closing distances
// |n . d| (metres over the whole sweep). Why that form: each entry time p / v is off by at most
// eps / |v| when p is right to eps metres, and toi is the largest entry, so it is off by at most
// eps over the closing distance of whichever axis wins in either computation.
#include "compare/exact/exact_sweep.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "../geometry/random_cases2.hpp"
#include "../geometry/sweep_cases.hpp"
#include "geometry/sweep_obb2.hpp"
#include "geometry/sweep_polygon.hpp"

namespace cardemo {
namespace {

using testing::Failures;
using testing::kSweepTolerance;
using testing::Random;
using testing::scaledCount;

Obb2 axisBox(double x, double y, double length, double width) {
  return {{x, y}, {1.0, 0.0}, {0.5 * length, 0.5 * width}};
}

TEST(ExactSweep, HeadOnTimeIsExact) {
  // 5 m gap: a 3 m displacement stops short, a 15 m one touches at t = 1/3.
  EXPECT_FALSE(exact::sweepObb2(axisBox(0, 0, 4, 2), {3.0, 0.0}, axisBox(8, 0.5, 2, 2)).hit);
  const exact::ExactSweep far =
      exact::sweepObb2(axisBox(0, 0, 4, 2), {15.0, 0.0}, axisBox(8, 0.5, 2, 2));
  ASSERT_TRUE(far.hit);
  EXPECT_EQ(far.toi, 5.0 / 15.0);  // 1/3 rounded to nearest
  EXPECT_EQ(far.normal, Eigen::Vector2d(1.0, 0.0));
  EXPECT_EQ(far.closing, 15.0);
}

TEST(ExactSweep, TouchingAtTheEndAndStartingInContact) {
  const Obb2 a = axisBox(0, 0, 4, 2);
  EXPECT_EQ(exact::sweepObb2(a, {5.0, 0.0}, axisBox(8, 0, 2, 2)).toi, 1.0);
  EXPECT_FALSE(exact::sweepObb2(a, {std::nextafter(5.0, 0.0), 0.0}, axisBox(8, 0, 2, 2)).hit);
  const exact::ExactSweep start = exact::sweepObb2(a, {-5.0, 0.0}, axisBox(3, 0, 2, 2));
  ASSERT_TRUE(start.hit);
  EXPECT_EQ(start.toi, 0.0);
  EXPECT_EQ(start.normal, Eigen::Vector2d(1.0, 0.0));
  EXPECT_TRUE(exact::sweepObb2(a, {0.0, 0.0}, axisBox(1, 0.5, 2, 2)).hit);
  EXPECT_FALSE(exact::sweepObb2(a, {0.0, 0.0}, axisBox(3.5, 0, 2, 2)).hit);
}

TEST(ExactSweep, ParallelMotionAndTinyGapsAreExact) {
  const Obb2 a = axisBox(1e7, 1e7, 4, 2);
  const Obb2 beside = axisBox(1e7, 1e7 + 2 + std::ldexp(1.0, -29), 4, 2);  // 1 ulp at 1e7 above
  EXPECT_FALSE(exact::sweepObb2(a, {1e6, 0.0}, beside).hit);
  EXPECT_TRUE(exact::sweepObb2(a, {1e6, 0.0}, axisBox(1e7, 1e7 + 2, 4, 2)).hit);
  const std::vector<Eigen::Vector2d> kerb{{50, -5}, {50.05, -5}, {50.05, 5}, {50, 5}};
  const exact::ExactSweep r = exact::sweepObbPolygon(axisBox(0, 0, 4.5, 1.8), {1000.0, 0.0},
                                                     *ConvexPolygon::fromPoints(kerb));
  ASSERT_TRUE(r.hit);
  EXPECT_EQ(r.toi, (50.0 - 2.25) / 1000.0);
  EXPECT_EQ(r.normal, Eigen::Vector2d(1.0, 0.0));
}

TEST(ExactSweep, InflateWidensTheMovingShape) {
  const Obb2 a = axisBox(0, 0, 4, 2);
  const Obb2 b = axisBox(0, 3 + 1e-7, 4, 4);  // 1e-7 m gap across the motion
  EXPECT_FALSE(exact::sweepObb2(a, {10.0, 0.0}, b).hit);
  EXPECT_TRUE(exact::sweepObb2(a, {10.0, 0.0}, b, 2e-7).hit);
  EXPECT_FALSE(exact::sweepObb2(a, {10.0, 0.0}, axisBox(0, 3, 4, 4), -1e-9).hit);
}

struct SweepStats {
  int cases = 0, hits = 0, borderline = 0;
  double max_scaled_error = 0.0;  // max |toi - toi*| * c, metres
  double max_ratio = 0.0;         // the same in units of 2^-53 times the query's length scale
};

// Unit roundoff of double, and the asserted bound in those units: |toi - toi*| * c stays within
// kRoundoffBound * u * (|centre offset| + A's half sides + B's size + |d|).
constexpr double kUnitRoundoff = 0x1p-53;
constexpr double kRoundoffBound = 64.0;

Eigen::Vector2d b_centre(const Obb2& b) {
  return b.center;
}
Eigen::Vector2d b_centre(const ConvexPolygon& b) {
  return b.centroid();
}
double b_size(const Obb2& b) {
  return b.half.sum();
}
double b_size(const ConvexPolygon& b) {
  return testing::polygonReach(b);
}

template <class Shape, class Fast, class Oracle>
SweepStats checkAgainstOracle(const char* label, int count, std::uint64_t seed, Fast fast,
                              Oracle oracle) {
  Random rng(seed);
  Failures f;
  SweepStats stats;
  for (int i = 0; i < count; ++i) {
    const auto [b, c] = testing::sweepTarget<Shape>(rng);
    const SweepResult2 r = fast(c.a, c.d, b);
    const exact::ExactSweep x = oracle(c.a, c.d, b, 0.0);
    ++stats.cases;
    if (x.hit) ++stats.hits;
    if (r.hit != x.hit) {
      const bool wide = oracle(c.a, c.d, b, kSweepTolerance).hit;
      const bool narrow = oracle(c.a, c.d, b, -kSweepTolerance).hit;
      if (wide != narrow) {
        ++stats.borderline;
      } else {
        f.check(false, i, std::string("verdict differs: fast ") + (r.hit ? "hit" : "miss"));
      }
      continue;
    }
    if (!r.hit) continue;
    const double closing_fast = r.toi > 0.0 ? std::abs(r.normal.dot(c.d)) : INFINITY;
    const double closing_exact = x.toi > 0.0 ? x.closing : INFINITY;
    const double closing = std::min(closing_fast, closing_exact);
    const double err = r.toi == x.toi ? 0.0 : std::abs(r.toi - x.toi) * closing;
    stats.max_scaled_error = std::max(stats.max_scaled_error, err);
    f.check(err <= kSweepTolerance, i,
            "toi " + std::to_string(r.toi) + " vs exact " + std::to_string(x.toi) +
                ", error x closing " + std::to_string(err));
    // The rounding behind it: a few ulps of the lengths the query combines.
    const double scale =
        (b_centre(b) - c.a.center).norm() + c.a.half.sum() + b_size(b) + c.d.norm();
    const double ratio = err / (scale * kUnitRoundoff);
    stats.max_ratio = std::max(stats.max_ratio, ratio);
    f.check(ratio <= kRoundoffBound, i,
            "toi error is " + std::to_string(ratio) + " ulps of the scale");
    if (r.toi > 0.0 && x.toi > 0.0 && err == 0.0) {
      f.check((r.normal - x.normal).norm() <= 1e-9 || std::abs(r.toi - x.toi) == 0.0, i,
              "normal differs");
    }
  }
  EXPECT_EQ(f.count(), 0) << label << "\n" << f.report();
  EXPECT_GT(stats.hits, count / 5) << label;
  EXPECT_LT(stats.borderline, count / 1000 + 1) << label;
  std::cout << label << ": " << stats.cases << " cases, " << stats.hits << " hits, "
            << stats.borderline << " borderline, max |toi error| x closing "
            << stats.max_scaled_error << " m (" << stats.max_ratio << " ulps of the scale)\n";
  return stats;
}

TEST(ExactSweep, RandomBoxesMatchTheOracle) {
  checkAgainstOracle<Obb2>(
      "boxes", scaledCount(100000), 0xc0ffee1,
      [](const Obb2& a, const Eigen::Vector2d& d, const Obb2& b) { return sweepObb2(a, d, b); },
      [](const Obb2& a, const Eigen::Vector2d& d, const Obb2& b, double inflate) {
        return exact::sweepObb2(a, d, b, inflate);
      });
}

TEST(ExactSweep, RandomPolygonsMatchTheOracle) {
  checkAgainstOracle<ConvexPolygon>(
      "polygons", scaledCount(100000), 0xc0ffee2,
      [](const Obb2& a, const Eigen::Vector2d& d, const ConvexPolygon& b) {
        return sweepObbPolygon(a, d, b);
      },
      [](const Obb2& a, const Eigen::Vector2d& d, const ConvexPolygon& b, double inflate) {
        return exact::sweepObbPolygon(a, d, b, inflate);
      });
}

}  // namespace
}  // namespace cardemo
