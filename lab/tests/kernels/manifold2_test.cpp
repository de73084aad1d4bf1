#include "lab/kernels/manifold2.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "compare/exact/exact_sat.hpp"
#include "geometry/sat_obb2.hpp"
#include "manifold_margin.hpp"
#include "tests/geometry/random_cases2.hpp"

namespace cardemo {
namespace {

using testing::Failures;
using testing::Random;

// How far a point is outside (> 0) or inside (< 0) a box, along the box's own axes.
double boxDistance(const Obb2& box, const Eigen::Vector2d& p) {
  const Eigen::Vector2d d = p - box.center;
  const double x = std::abs(d.dot(box.axis)) - box.half.x();
  const double y = std::abs(d.dot(box.perp())) - box.half.y();
  return std::max(x, y);
}

Obb2 box(double x, double y, double heading_deg, double length, double width) {
  return Obb2::fromDegrees({x, y}, heading_deg, length, width);
}

TEST(Manifold2, BoxRestingFlatGivesTwoPoints) {
  const Obb2 ground = box(0, 0, 0, 4, 2);
  const Obb2 crate = box(0.25, 1.99, 0, 2, 2);  // 1 cm into the ground's top face
  const Manifold2 m = manifoldObb2(ground, crate);
  ASSERT_EQ(m.count, 2);
  EXPECT_EQ(m.reference_face, 1);  // A's +y face wins the tie with B's -y face
  EXPECT_EQ(m.normal, Eigen::Vector2d(0, 1));
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(m.points[i].separation, -0.01, 1e-12);
    EXPECT_NEAR(m.points[i].point.y(), 0.99, 1e-12);
    EXPECT_NEAR(boxDistance(crate, m.points[i].point), 0.0, 1e-12);
  }
  EXPECT_NEAR(std::min(m.points[0].point.x(), m.points[1].point.x()), -0.75, 1e-12);
  EXPECT_NEAR(std::max(m.points[0].point.x(), m.points[1].point.x()), 1.25, 1e-12);
  EXPECT_NE(m.points[0].feature, m.points[1].feature);
}

TEST(Manifold2, OverhangingBoxIsClippedToTheReferenceFace) {
  const Obb2 ground = box(0, 0, 0, 4, 2);
  const Obb2 plank = box(2.5, 1.5, 0, 3, 1);  // overhangs the right end; exactly touching
  const Manifold2 m = manifoldObb2(ground, plank);
  ASSERT_EQ(m.count, 2);
  EXPECT_EQ(m.normal, Eigen::Vector2d(0, 1));
  EXPECT_EQ(m.points[0].separation, 0.0);
  EXPECT_EQ(m.points[1].separation, 0.0);
  EXPECT_NEAR(std::max(m.points[0].point.x(), m.points[1].point.x()), 2.0, 1e-12);
  EXPECT_NEAR(std::min(m.points[0].point.x(), m.points[1].point.x()), 1.0, 1e-12);
}

TEST(Manifold2, CornerIntoFaceGivesOnePoint) {
  const Obb2 ground = box(0, 0, 0, 4, 2);
  const Obb2 diamond = box(0, 1 + std::sqrt(2.0) - 0.1, 45, 2, 2);  // lowest corner 0.1 deep
  const Manifold2 m = manifoldObb2(ground, diamond);
  ASSERT_EQ(m.count, 1);
  EXPECT_EQ(m.reference_face, 1);
  EXPECT_NEAR(m.points[0].separation, -0.1, 1e-12);
  EXPECT_NEAR(m.points[0].point.x(), 0.0, 1e-12);
  EXPECT_NEAR(m.points[0].point.y(), 0.9, 1e-12);
}

TEST(Manifold2, FaceOfBAsReferencePutsPointsOnB) {
  const Obb2 diamond = box(0, 0, 45, 2, 2);
  const Obb2 ground = box(0.5, -1 - std::sqrt(2.0) + 0.1, 0, 6, 2);
  const Manifold2 m = manifoldObb2(diamond, ground);
  ASSERT_EQ(m.count, 1);
  EXPECT_EQ(m.reference_face, 5);  // B's +y face
  EXPECT_NEAR(m.normal.x(), 0.0, 1e-15);
  EXPECT_NEAR(m.normal.y(), -1.0, 1e-15);
  EXPECT_NEAR(m.points[0].separation, -0.1, 1e-12);
  EXPECT_NEAR(boxDistance(ground, m.points[0].point), 0.0, 1e-12);
  EXPECT_NEAR(m.points[0].point.x(), 0.0, 1e-12);
}

TEST(Manifold2, HysteresisKeepsThePreviousFace) {
  const Obb2 a = box(0, 0, 0, 2, 2);
  // Overlap 0.1 along x and 0.1 - 1e-4 along y: +y is (barely) the SAT face.
  const Obb2 b = box(1.9, 1.9 + 1e-4, 0, 2, 2);
  EXPECT_EQ(manifoldObb2(a, b).reference_face, 1);
  const Manifold2 kept = manifoldObb2(a, b, {}, 0);
  EXPECT_EQ(kept.reference_face, 0);
  EXPECT_EQ(kept.normal, Eigen::Vector2d(1, 0));
  EXPECT_GT(kept.count, 0);
  // A clear winner (0.05 m better) replaces the previous face.
  const Obb2 c = box(1.9, 1.95, 0, 2, 2);
  EXPECT_EQ(manifoldObb2(a, c, {}, 0).reference_face, 1);
}

TEST(Manifold2, SeparatedGivesNoPoints) {
  const Manifold2 m = manifoldObb2(box(0, 0, 0, 2, 2), box(3, 0.5, 30, 2, 2));
  EXPECT_EQ(m.count, 0);
  EXPECT_EQ(m.reference_face, -1);
  const Manifold2 near = manifoldObb2(box(0, 0, 0, 2, 2), box(2.05, 0, 0, 2, 2), {0.1});
  ASSERT_EQ(near.count, 2) << "within max_separation the points are speculative contacts";
  EXPECT_NEAR(near.points[0].separation, 0.05, 1e-12);
}

TEST(Manifold2, FarFromOrigin) {
  const Obb2 ground = box(1e7, -1e7, 90, 4, 2);
  const Obb2 crate = box(1e7 - 1.99, -1e7, 90, 2, 2);
  const Manifold2 m = manifoldObb2(ground, crate);
  ASSERT_EQ(m.count, 2);
  EXPECT_NEAR(m.normal.x(), -1.0, 1e-15);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(m.points[i].separation, -0.01, 1e-9);
    EXPECT_NEAR(boxDistance(crate, m.points[i].point), 0.0, 1e-8);
  }
}

// How much worse than the SAT separation S a kept face may be: either the previous face within
// margin(S), or A's face F that B failed to beat by margin(F), i.e. F >= (S - abs) / rel.
double worstKept(const ManifoldSettings& s, double sat) {
  return std::max(testing::manifoldMargin(s, sat),
                  sat - (sat - s.absolute_tolerance) / s.relative_tolerance);
}

TEST(Manifold2Random, PointsAgreeWithExactSat) {
  Random rng(3001);
  Failures f;
  const int n = testing::scaledCount(50000);
  int with_points = 0;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d base = rng.offset(0, 100);
    const Obb2 a = rng.box(base, 0.1, 10.0);
    Obb2 b = rng.box(base, 0.1, 10.0);
    b.center += rng.offset(0, 1.1 * (a.half.norm() + b.half.norm()));
    const exact::ExactResult ex = exact::collideObb2(a, b);
    const SatResult2 sat = collideObb2(a, b);
    const ManifoldSettings strict{0.0, 1.0, 0.0};
    const ManifoldSettings usual{};
    for (const ManifoldSettings& s : {strict, usual}) {
      const Manifold2 m = manifoldObb2(a, b, s);
      f.check((m.count > 0) == sat.hit, i, "count>0 differs from the SAT hit");
      if (std::abs(ex.separation) > testing::kHitTolerance) {
        f.check((m.count > 0) == ex.hit, i, "count>0 differs from the exact hit");
      }
      if (m.count == 0) continue;
      f.check(std::abs(m.normal.norm() - 1.0) <= 1e-12, i, "normal not unit");
      const double allowed = s.relative_tolerance == 1.0 ? 0.0 : worstKept(s, ex.separation);
      for (int k = 0; k < m.count; ++k) {
        const ContactPoint2& p = m.points[k];
        f.check(p.separation >= ex.separation - allowed - 1e-9, i,
                "point separation " + std::to_string(p.separation) + " below exact SAT " +
                    std::to_string(ex.separation));
        f.check(p.separation <= s.max_separation, i, "point beyond max_separation");
        f.check(std::abs(boxDistance(b, p.point)) <= 1e-9, i, "point not on B's surface");
        // The point lies `separation` away from A's surface along the normal, or inside it.
        f.check(boxDistance(a, p.point - p.separation * m.normal) <= 1e-9, i,
                "point minus separation is not on A");
      }
      if (s.relative_tolerance == 1.0) {
        const auto ca = a.corners(), cb = b.corners();
        f.check(std::abs(testing::signedGap(ca, cb, m.normal, a.center) - ex.separation) <= 1e-9, i,
                "normal is not the SAT axis");
        ++with_points;
      }
    }
    // Hysteresis never keeps a face that is worse than the SAT face by more than the margin.
    const int previous = rng.integer(0, 7);
    const Manifold2 h = manifoldObb2(a, b, usual, previous);
    if (h.count > 0 && h.reference_face != previous) {
      f.check(h.reference_face >= 0 && h.reference_face < 8, i, "bad reference face");
    }
    for (int k = 0; k < h.count; ++k) {
      f.check(h.points[k].separation >= ex.separation - worstKept(usual, ex.separation) - 1e-9, i,
              "hysteresis kept a face beyond the tolerance");
    }
  }
  EXPECT_EQ(f.count(), 0) << f.report();
  EXPECT_GT(with_points, n / 10);
}

// The manifold's verdict (a point or none, max_separation 0) is the exact oracle's on every pair
// outside the contract's 1e-6 m band, near touching and at the distances from the origin that
// `cardemo compare-sweep` visits: so the cost-versus-error plot (docs/box2d-comparison.md) may put
// manifoldObb2 at the sweep's error for cardemo.
TEST(Manifold2Random, VerdictIsExactNearTouchingFarOut) {
  Random rng(3003);
  Failures f;
  const int n = testing::scaledCount(20000);
  const double offsets[] = {0.0, 1e3, 1e5, 1e7};
  int judged = 0;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d base = offsets[i % 4] * rng.direction() + rng.offset(0.0, 10.0);
    const Obb2 a = rng.box(base, 0.1, 20.0);
    Obb2 b = rng.box(base, 0.1, 20.0);
    // B clear of A along a random direction, then slid along the SAT normal to a signed gap
    // log-uniform in [1e-9, 1] m (as the sweep places its pairs).
    b.center = a.center + (a.half.norm() + b.half.norm() + 1.0) * rng.direction();
    const SatResult2 start = collideObb2(a, b);
    b.center += (rng.signedLogUniform(1e-9, 1.0) - start.separation) * start.normal;
    const exact::ExactResult ex = exact::collideObb2(a, b);
    if (std::abs(ex.separation) <= testing::kHitTolerance) continue;
    ++judged;
    const Manifold2 m = manifoldObb2(a, b, ManifoldSettings{0.0, 1.0, 0.0});
    f.check((m.count > 0) == ex.hit, i, "count>0 differs from the exact verdict");
    const Manifold2 usual = manifoldObb2(a, b, ManifoldSettings{});
    f.check((usual.count > 0) == ex.hit, i, "count>0 (usual settings) differs from exact");
  }
  EXPECT_EQ(f.count(), 0) << f.report();
  EXPECT_GT(judged, n / 2);
}

TEST(Manifold2, IncidentFaceTieTakesTheFirstFace) {
  // B turned exactly 45 degrees against A (both axis components the same double), a corner 1 cm
  // into A's top face: B's faces 2 and 3 are equally anti-parallel to the reference normal. The
  // first of them (face 2, corners 2 and 3) is the incident edge, as a scan in face order takes
  // it; face 3 would give corners 3 and 0. Both corners stay within the wide max_separation.
  const Obb2 ground = box(0, 0, 0, 4, 2);
  const double r = std::sqrt(0.5);
  const Obb2 tilted{{0.0, 1.0 + r - 0.01}, {r, r}, {0.5, 0.5}};
  ManifoldSettings wide;
  wide.max_separation = 1.0;
  const Manifold2 m = manifoldObb2(ground, tilted, wide);
  ASSERT_EQ(m.reference_face, 1);
  ASSERT_EQ(m.count, 2);
  EXPECT_EQ(m.points[0].feature, 8 * 1 + 2);
  EXPECT_EQ(m.points[1].feature, 8 * 1 + 3);  // B's lowest corner, (-, -)
  EXPECT_NEAR(m.points[1].separation, -0.01, 1e-12);
}

}  // namespace
}  // namespace cardemo
