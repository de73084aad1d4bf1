// Swept SAT (sweep_obb2, sweep_polygon): named edge cases, and seeded random cases checked against
// the static SAT sampled along the sweep (its slow twin). The exact oracle check is in
// tests/exact/exact_sweep_test.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/convex_polygon.hpp"
#include "geometry/sat_obb2.hpp"
#include "geometry/sweep_obb2.hpp"
#include "geometry/sweep_polygon.hpp"
#include "random_cases2.hpp"
#include "sweep_cases.hpp"

namespace cardemo {
namespace {

using testing::Failures;
using testing::kSweepTolerance;
using testing::Random;
using testing::scaledCount;

Obb2 axisBox(double x, double y, double length, double width) {
  return {{x, y}, {1.0, 0.0}, {0.5 * length, 0.5 * width}};
}

ConvexPolygon square(double x0, double y0, double x1, double y1) {
  const Eigen::Vector2d pts[] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  return *ConvexPolygon::fromPoints(pts);
}

Obb2 moved(Obb2 box, const Eigen::Vector2d& d, double t) {
  box.center += d * t;
  return box;
}

TEST(Sweep, HeadOnContactTimeAndNormal) {
  // A (4 x 2 at the origin) moves 10 m along +x; B's rear face is at x = 7: contact at t = 0.5.
  const Obb2 a = axisBox(0.0, 0.0, 4.0, 2.0);
  const Obb2 b = axisBox(8.0, 0.5, 2.0, 2.0);
  const SweepResult2 r = sweepObb2(a, {10.0, 0.0}, b);
  ASSERT_TRUE(r.hit);
  EXPECT_EQ(r.toi, 0.5);
  EXPECT_EQ(r.normal, Eigen::Vector2d(1.0, 0.0));
  EXPECT_EQ(r.start_separation, 5.0);
  const SweepResult2 p = sweepObbPolygon(a, {10.0, 0.0}, square(7.0, -0.5, 9.0, 1.5));
  ASSERT_TRUE(p.hit);
  EXPECT_EQ(p.toi, 0.5);
  EXPECT_EQ(p.normal, Eigen::Vector2d(1.0, 0.0));
}

TEST(Sweep, TouchingExactlyAtTheEndIsAHitAtOne) {
  const Obb2 a = axisBox(0.0, 0.0, 4.0, 2.0);
  const Obb2 b = axisBox(8.0, 0.0, 2.0, 2.0);  // rear face at x = 7: A's front reaches it at t = 1
  const SweepResult2 r = sweepObb2(a, {5.0, 0.0}, b);
  ASSERT_TRUE(r.hit);
  EXPECT_EQ(r.toi, 1.0);
  EXPECT_FALSE(sweepObb2(a, {std::nextafter(5.0, 0.0), 0.0}, b).hit);
  const ConvexPolygon kerb = square(7.0, -5.0, 7.05, 5.0);
  EXPECT_EQ(sweepObbPolygon(a, {5.0, 0.0}, kerb).toi, 1.0);
  EXPECT_FALSE(sweepObbPolygon(a, {std::nextafter(5.0, 0.0), 0.0}, kerb).hit);
}

TEST(Sweep, GrazingAlongAFaceTouches) {
  // A's top face slides along B's bottom face (y = 1): touching counts, from the moment the x
  // intervals meet; a hair lower is the same, a hair higher never touches.
  const Obb2 a = axisBox(0.0, 0.0, 4.0, 2.0);
  const Obb2 b = axisBox(10.0, 2.0, 2.0, 2.0);
  const SweepResult2 r = sweepObb2(a, {20.0, 0.0}, b);
  ASSERT_TRUE(r.hit);
  EXPECT_EQ(r.toi, 7.0 / 20.0);
  EXPECT_EQ(r.normal, Eigen::Vector2d(1.0, 0.0));  // the last axis to start overlapping
  EXPECT_FALSE(sweepObb2(a, {20.0, 0.0}, axisBox(10.0, std::nextafter(2.0, 3.0), 2.0, 2.0)).hit);
  const ConvexPolygon above = square(9.0, 1.0, 11.0, 3.0);
  EXPECT_TRUE(sweepObbPolygon(a, {20.0, 0.0}, above).hit);
  EXPECT_FALSE(sweepObbPolygon(a, {20.0, 0.0}, square(9.0, 1.0 + 1e-12, 11.0, 3.0)).hit);
}

TEST(Sweep, GrazingCornerToCornerTouchesAtOneInstant) {
  // A's bottom-right corner (2, -1) moves by (4, 4) and passes exactly through B's top-left corner
  // (4, 1) at t = 0.5: the boxes touch at that single point and part again.
  const Obb2 a = axisBox(0.0, 0.0, 4.0, 2.0);
  const Obb2 b = axisBox(6.0, -1.0, 4.0, 4.0);
  const SweepResult2 r = sweepObb2(a, {4.0, 4.0}, b);
  ASSERT_TRUE(r.hit);
  EXPECT_EQ(r.toi, 0.5);
  EXPECT_EQ(r.normal, Eigen::Vector2d(1.0, 0.0));
  // Aimed a hair higher it misses; a hair lower it hits the top-left corner's face.
  EXPECT_FALSE(sweepObb2(a, {4.0, std::nextafter(4.0, 5.0)}, b).hit);
  EXPECT_TRUE(sweepObb2(a, {4.0, std::nextafter(4.0, 3.0)}, b).hit);
  const ConvexPolygon pb = square(4.0, -3.0, 8.0, 1.0);
  EXPECT_EQ(sweepObbPolygon(a, {4.0, 4.0}, pb).toi, 0.5);
  EXPECT_FALSE(sweepObbPolygon(a, {4.0, std::nextafter(4.0, 5.0)}, pb).hit);
}

TEST(Sweep, MotionParallelToAFaceNeverCloses) {
  // A gap of 1e-9 m across a face and a displacement exactly along it: no contact however far.
  const Obb2 a = axisBox(0.0, 0.0, 4.0, 2.0);
  const Obb2 b = axisBox(0.0, 2.0 + 1e-9, 4.0, 2.0);
  EXPECT_FALSE(sweepObb2(a, {1e6, 0.0}, b).hit);
  EXPECT_FALSE(sweepObb2(a, {-1e6, 0.0}, b).hit);
  // Rotated frame: a 30-degree box moving exactly along its own axis beside a parallel box.
  const Obb2 ra = Obb2::fromDegrees({1e7, -1e7}, 90.0, 4.0, 2.0);
  const Obb2 rb = Obb2::fromDegrees({1e7 + 2.5, -1e7}, 90.0, 4.0, 2.0);
  EXPECT_FALSE(sweepObb2(ra, {0.0, 500.0}, rb).hit);
  EXPECT_TRUE(
      sweepObb2(ra, {0.0, 500.0}, Obb2::fromDegrees({1e7 + 2.0, -1e7 + 50.0}, 90.0, 4.0, 2.0)).hit);
  EXPECT_FALSE(sweepObbPolygon(a, {1e6, 0.0}, square(-5.0, 1.0 + 1e-9, 5.0, 3.0)).hit);
}

TEST(Sweep, ZeroDisplacementIsTheStaticTest) {
  const Obb2 a = Obb2::fromDegrees({1.0, 2.0}, 17.0, 4.5, 1.8);
  for (const double x : {3.0, 4.0, 5.0, 6.0}) {
    const Obb2 b = Obb2::fromDegrees({x, 2.5}, -40.0, 4.5, 1.8);
    const SatResult2 s = collideObb2(a, b);
    const SweepResult2 r = sweepObb2(a, Eigen::Vector2d::Zero(), b);
    EXPECT_EQ(r.hit, s.hit) << x;
    EXPECT_EQ(r.start_separation, s.separation);
    if (r.hit) {
      EXPECT_EQ(r.toi, 0.0);
      EXPECT_EQ(r.normal, s.normal);
    }
  }
}

TEST(Sweep, StartingInContactGivesToiZeroWithTheStaticNormal) {
  const Obb2 a = axisBox(0.0, 0.0, 4.0, 2.0);
  const Obb2 touching = axisBox(3.0, 0.0, 2.0, 2.0);  // faces meet at x = 2
  for (const Eigen::Vector2d& d :
       {Eigen::Vector2d(5.0, 0.0), Eigen::Vector2d(-5.0, 0.0), Eigen::Vector2d(0.0, 7.0)}) {
    const SweepResult2 r = sweepObb2(a, d, touching);
    ASSERT_TRUE(r.hit);
    EXPECT_EQ(r.toi, 0.0);
    EXPECT_EQ(r.normal, Eigen::Vector2d(1.0, 0.0));
    EXPECT_EQ(r.start_separation, 0.0);
  }
  const Obb2 overlapping = Obb2::fromDegrees({2.5, 0.3}, 30.0, 2.0, 2.0);
  const SatResult2 s = collideObb2(a, overlapping);
  const SweepResult2 r = sweepObb2(a, {-30.0, 1.0}, overlapping);
  ASSERT_TRUE(r.hit);
  EXPECT_EQ(r.toi, 0.0);
  EXPECT_EQ(r.normal, s.normal);
  EXPECT_EQ(r.start_separation, s.separation);
  const ConvexPolygon poly = ConvexPolygon::fromObb(overlapping);
  const SatResult2 ps = collideObbPolygon(a, poly);
  const SweepResult2 pr = sweepObbPolygon(a, {-30.0, 1.0}, poly);
  ASSERT_TRUE(pr.hit);
  EXPECT_EQ(pr.toi, 0.0);
  EXPECT_EQ(pr.normal, ps.normal);
  EXPECT_EQ(pr.start_separation, ps.separation);
}

TEST(Sweep, ThinKerbAtAnySpeedIsHit) {
  // A 5 cm kerb and a displacement of up to 1 km: the sweep has no step to skip over it.
  const Obb2 a = Obb2::fromDegrees({0.0, 0.0}, 0.0, 4.5, 1.8);
  const ConvexPolygon kerb = square(50.0, -5.0, 50.05, 5.0);
  for (const double distance : {60.0, 100.0, 1000.0}) {
    const SweepResult2 r = sweepObbPolygon(a, {distance, 0.0}, kerb);
    ASSERT_TRUE(r.hit) << distance;
    EXPECT_NEAR(r.toi * distance, 50.0 - 2.25, 1e-12);
    EXPECT_EQ(r.normal, Eigen::Vector2d(1.0, 0.0));
  }
}

// Random cases against the static SAT sampled along the sweep: before the reported contact the
// shapes are apart, at it they touch (within the tolerance), and a miss is apart everywhere.
// `start_tolerance`: how far the sweep's gap at t = 0 may be from the static separation (0 where
// both do the same operations in the same order).
template <class Shape, class Sweep, class Static>
void checkAgainstSampledStatic(const char* label, int count, std::uint64_t seed, Sweep sweep,
                               Static collide, double start_tolerance) {
  Random rng(seed);
  Failures f;
  int hits = 0, starts = 0;
  for (int i = 0; i < count; ++i) {
    const auto [b, c] = testing::sweepTarget<Shape>(rng);
    const SweepResult2 r = sweep(c.a, c.d, b);
    const SatResult2 s0 = collide(c.a, b);
    f.check(std::abs(r.start_separation - s0.separation) <= start_tolerance, i,
            "start separation differs from the static SAT");
    f.check(!s0.hit || s0.separation >= -start_tolerance || (r.hit && r.toi == 0.0), i,
            "in contact at t = 0 but toi is not 0");
    f.check(std::abs(r.normal.norm() - 1.0) <= 1e-12, i, "normal not unit");
    if (r.hit) ++hits;
    if (r.hit && r.toi == 0.0) ++starts;
    if (r.hit && r.toi > 0.0) {
      f.check(r.toi <= 1.0, i, "toi beyond 1");
      f.check(r.normal.dot(c.d) > 0.0, i, "contact normal does not face the motion");
      const double at = collide(moved(c.a, c.d, r.toi), b).separation;
      f.check(std::abs(at) <= kSweepTolerance, i, "separation at the toi is " + std::to_string(at));
      for (int k = 0; k < 8; ++k) {
        const double t = r.toi * k / 8.0;
        f.check(collide(moved(c.a, c.d, t), b).separation > -kSweepTolerance, i,
                "overlap before the toi at t = " + std::to_string(t));
      }
    }
    if (!r.hit) {
      for (int k = 0; k <= 16; ++k) {
        const double t = k / 16.0;
        f.check(collide(moved(c.a, c.d, t), b).separation > -kSweepTolerance, i,
                "reported a miss but overlaps at t = " + std::to_string(t));
      }
    }
  }
  EXPECT_EQ(f.count(), 0) << label << "\n" << f.report();
  // The generator must exercise all three outcomes.
  EXPECT_GT(hits, count / 5) << label;
  EXPECT_GT(count - hits, count / 5) << label;
  EXPECT_GT(starts, count / 200) << label;
}

TEST(Sweep, RandomBoxesAgreeWithTheSampledStaticTest) {
  checkAgainstSampledStatic<Obb2>(
      "boxes", scaledCount(100000), 0x5eed0b,
      [](const Obb2& a, const Eigen::Vector2d& d, const Obb2& b) { return sweepObb2(a, d, b); },
      [](const Obb2& a, const Obb2& b) { return collideObb2(a, b); }, 0.0);
}

TEST(Sweep, RandomPolygonsAgreeWithTheSampledStaticTest) {
  checkAgainstSampledStatic<ConvexPolygon>(
      "polygons", scaledCount(100000), 0x5eed0c,
      [](const Obb2& a, const Eigen::Vector2d& d, const ConvexPolygon& b) {
        return sweepObbPolygon(a, d, b);
      },
      // collideObbPolygon projects relative to its own reference point, two axes at a time, and
      // normalises only the winning axis: the same gaps to within rounding, not bit for bit.
      [](const Obb2& a, const ConvexPolygon& b) { return collideObbPolygon(a, b); }, 1e-12);
}

}  // namespace
}  // namespace cardemo
