/// 3D OBB SAT against the exact GMP oracle: seeded random classes, both argument orders.

#include "geometry/obb3.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>

#include "../support/random_class.hpp"
#include "compare/exact/exact_sat.hpp"
#include "random_cases3.hpp"

namespace cardemo {
namespace {

using test3::describe;
using test3::Pair3;
using testing::ClassStats;
using testing::Failures;
using testing::kCasesPerClass;
using testing::kHitTolerance;
using testing::kSepTolerance;

// Checks one pair in both orders against the oracle (computed once: the oracle is symmetric, which
// exact_sat3_test checks). `strictHit`: the oracle's hit must be matched even inside 1e-6 m.
void checkPair(const Pair3& p, int index, Failures& f, ClassStats& s, bool strictHit = false,
               const exact::ExactResult* known = nullptr) {
  const exact::ExactResult ex = known != nullptr ? *known : exact::collideObb3(p.a, p.b);
  const SatResult3 ab = collideObb3(p.a, p.b);
  const SatResult3 ba = collideObb3(p.b, p.a);
  s.tally(ex.hit, ex.separation);
  s.countAxis(ab.axis_index >= 6);
  const bool checkHit = strictHit || std::abs(ex.separation) > kHitTolerance;
  for (const auto& [r, x, y] : {std::tuple{ab, &p.a, &p.b}, std::tuple{ba, &p.b, &p.a}}) {
    const auto fail = [&, x = x, y = y](const std::string& what) {
      f.fail(index, what + "\n" + describe(*x, *y));
    };
    const double err = std::abs(r.separation - ex.separation);
    s.max_error = std::max(s.max_error, err);
    // Formatted only for a failure.
    const auto verdicts = [&, r = r]() {
      std::ostringstream m;
      m.precision(17);
      m << "exact hit=" << ex.hit << " sep=" << ex.separation << "; got hit=" << r.hit
        << " sep=" << r.separation << " axis=" << r.axis_index;
      return m.str();
    };
    if (!(err <= kSepTolerance)) fail("separation off: " + verdicts());
    if (checkHit && r.hit != ex.hit) fail("hit wrong: " + verdicts());
    if (overlapObb3(*x, *y) != r.hit) fail("overlapObb3 disagrees: " + verdicts());
    if (!(std::abs(r.normal.norm() - 1.0) <= 1e-12)) fail("normal not unit: " + verdicts());
    if (r.hit != (r.separation <= 0.0)) fail("hit inconsistent with sep: " + verdicts());
    // The normal points from the first box towards the second.
    const Eigen::Vector3d d = y->center - x->center;
    if (!(r.normal.dot(d) >= -1e-9 * (1.0 + d.norm()))) fail("normal points backwards");
  }
  const double asym = std::abs(ab.separation - ba.separation);
  s.noteAsymmetry(asym);
  if (!(asym <= 1e-9)) f.fail(index, "separation not symmetric\n" + describe(p.a, p.b));
}

// Runs `count` (scaled) cases of one generator through checkPair and asserts no failures.
void runBox3Class(const char* name, std::uint64_t seed,
                  const std::function<Pair3(std::mt19937_64&)>& gen, int count = kCasesPerClass,
                  bool strictHit = false) {
  const ClassStats s = testing::runRandomClass(
      name, seed, count, [&](std::mt19937_64& rng, int k, Failures& f, ClassStats& stats) {
        checkPair(gen(rng), k, f, stats, strictHit);
      });
  EXPECT_EQ(s.cases, test3::scaledCount(count));
}

TEST(Obb3Random, GapsBothSidesOfTouching) {
  runBox3Class("gaps", 0x0b3a0001, test3::gapPair);
}

TEST(Obb3Random, FarFromOrigin) {
  runBox3Class("far", 0x0b3a0002, test3::farPair);
}

TEST(Obb3Random, ExtremeSizesAndAspects) {
  runBox3Class("sizes", 0x0b3a0003, test3::sizePair);
}

TEST(Obb3Random, NearParallelEdges) {
  runBox3Class("near-parallel", 0x0b3a0004,
               [](std::mt19937_64& rng) { return test3::nearParallelPair(rng); });
}

TEST(Obb3Random, ExactlyCoincident) {
  runBox3Class("coincident", 0x0b3a0005, test3::coincidentPair);
}

TEST(Obb3Random, ExactlyParallel) {
  runBox3Class("parallel", 0x0b3a0006, test3::parallelPair);
}

TEST(Obb3Random, Containment) {
  runBox3Class("containment", 0x0b3a0007, test3::containmentPair);
}

TEST(Obb3Random, ExactTouchingAxisAligned) {
  // Exact touching must be a hit with separation exactly zero, not merely within 1e-6 m.
  runBox3Class("touching", 0x0b3a0008, test3::touchingPair, kCasesPerClass, true);
  std::mt19937_64 rng(0x0b3a0009);
  for (int k = 0; k < 1000; ++k) {
    const Pair3 p = test3::touchingPair(rng);
    EXPECT_EQ(collideObb3(p.a, p.b).separation, 0.0);
    EXPECT_TRUE(exact::collideObb3(p.a, p.b).hit);
  }
}

// Near-parallel edges at each named angle: overlapping or touching boxes are never reported as
// separated (strict: the oracle's verdict must be matched even below 1e-6 m).
TEST(Obb3NearParallel, NeverFalselySeparated) {
  const double angles[] = {1e-15, 1e-12, 1e-9, 1e-6, 1e-3};
  std::uint64_t seed = 0x0b3a0100;
  for (const double angle : angles) {
    std::mt19937_64 rng(seed++);
    Failures f;
    ClassStats t;
    int overlapping = 0;
    const int n = test3::scaledCount(20000);
    for (int k = 0; k < n; ++k) {
      Pair3 p = test3::nearParallelPair(rng, angle, angle);
      // Overlap by 1e-9..1e-3 m along the chosen axis; the oracle decides what is truly a hit.
      const Eigen::Vector3d d = p.b.center - p.a.center;
      if (d.norm() > 0.0) {
        const Eigen::Vector3d u = d.normalized();
        test3::placeAtGap(p.a, p.b, u, -test3::logUniform(rng, 1e-9, 1e-3));
      }
      const exact::ExactResult ex = exact::collideObb3(p.a, p.b);
      if (!ex.hit) continue;
      ++overlapping;
      EXPECT_TRUE(collideObb3(p.a, p.b).hit) << "angle " << angle << "\n" << describe(p.a, p.b);
      EXPECT_TRUE(collideObb3(p.b, p.a).hit) << "angle " << angle << "\n" << describe(p.a, p.b);
      EXPECT_TRUE(overlapObb3(p.a, p.b)) << "angle " << angle;
      EXPECT_TRUE(overlapObb3(p.b, p.a)) << "angle " << angle;
      checkPair(p, k, f, t, true, &ex);
    }
    std::printf("[ near-parallel %g rad ] %d overlapping pairs, worst |sep err| %.3g m\n", angle,
                overlapping, t.max_error);
    EXPECT_GT(overlapping, n / 50) << "too few overlapping cases at angle " << angle;
    EXPECT_EQ(f.count(), 0) << "angle " << angle << "\n" << f.report();
  }
}

// Two long beams, the second turned a quarter turn about z and then 1e-15..1e-3 rad about a tilted
// axis, crossed at their edges: the true separating axis is an edge-edge cross product.
TEST(Obb3NearParallel, CrossedBeamsSeparatedByAnEdgeAxis) {
  const double angles[] = {1e-15, 1e-12, 1e-9, 1e-6, 1e-3};
  for (const double angle : angles) {
    const Eigen::Quaterniond tilt(Eigen::AngleAxisd(angle, Eigen::Vector3d(1, 2, 3).normalized()));
    const Obb3 a =
        Obb3::fromQuaternion({1e7, -3e6, 2e5}, Eigen::Quaterniond::Identity(), {100.0, 0.5, 0.5});
    Obb3 b = Obb3::fromQuaternion({0, 0, 0}, tilt, {100.0, 0.5, 0.5});
    // Diagonal offset in A's yz plane puts B beyond A's long edge, off every face normal.
    const Eigen::Vector3d n = a.rotation().col(0).cross(b.rotation().col(0));
    ASSERT_GT(n.norm(), 0.0);
    for (const double gap : {-1e-3, -1e-7, 1e-7, 1e-3}) {
      const Eigen::Vector3d u = n.normalized();
      test3::placeAtGap(a, b, u, gap);
      const exact::ExactResult ex = exact::collideObb3(a, b);
      const SatResult3 r = collideObb3(a, b);
      EXPECT_NEAR(r.separation, ex.separation, kSepTolerance) << angle << " " << gap;
      EXPECT_EQ(r.hit, ex.hit) << angle << " " << gap;
      EXPECT_EQ(overlapObb3(b, a), ex.hit) << angle << " " << gap;
    }
  }
}

TEST(Obb3Quaternion, NormalisesAndIsOrthonormal) {
  std::mt19937_64 rng(0x0b3a0200);
  double worst = 0.0;
  for (int k = 0; k < 10000; ++k) {
    const Eigen::Quaterniond q = test3::randomRotation(rng);
    const Eigen::Vector3d c = test3::randomCenter(rng), s = test3::randomSize(rng);
    const Obb3 one = Obb3::fromQuaternion(c, q, s);
    const Obb3 two = Obb3::fromQuaternion(c, Eigen::Quaterniond(2.0 * q.coeffs()), s);
    const Obb3 tiny = Obb3::fromQuaternion(c, Eigen::Quaterniond(1e-200 * q.coeffs()), s);
    ASSERT_EQ(one.rotation(), two.rotation());
    ASSERT_TRUE(one.rotation().isApprox(tiny.rotation(), 1e-15));
    ASSERT_EQ(one.half, 0.5 * s);
    ASSERT_EQ(one.center, c);
    worst =
        std::max(worst, (one.rotation().transpose() * one.rotation() - Eigen::Matrix3d::Identity())
                            .cwiseAbs()
                            .maxCoeff());
    ASSERT_NEAR(one.rotation().determinant(), 1.0, 1e-14);
    // Same rotation as Eigen's, up to rounding.
    ASSERT_TRUE(one.rotation().isApprox(q.normalized().toRotationMatrix(), 1e-14));
  }
  EXPECT_LE(worst, 4e-15);  // a few ulps
}

TEST(Obb3Aabb, ContainsEveryCorner) {
  std::mt19937_64 rng(0x0b3a0300);
  for (int k = 0; k < 10000; ++k) {
    const Obb3 box = test3::randomBox(rng);
    const Aabb3 bounds = box.aabb();
    for (int c = 0; c < 8; ++c) {
      const Eigen::Vector3d p{(c & 1) ? 1.0 : -1.0, (c & 2) ? 1.0 : -1.0, (c & 4) ? 1.0 : -1.0};
      const Eigen::Vector3d corner = box.center + box.rotation() * p.cwiseProduct(box.half);
      // Loose: the corner itself is rounded; the bounds must be tight to a few ulps of 1e7.
      ASSERT_TRUE((bounds.min.array() <= corner.array() + 1e-8).all());
      ASSERT_TRUE((corner.array() <= bounds.max.array() + 1e-8).all());
    }
    ASSERT_LE((bounds.max - bounds.min - 2.0 * box.rotation().cwiseAbs() * box.half).norm(), 1e-8);
  }
}

TEST(Obb3Sat, AxisIndexAndNormalOnSimpleCases) {
  const Obb3 a = Obb3::fromQuaternion({0, 0, 0}, Eigen::Quaterniond::Identity(), {2, 2, 2});
  Obb3 b = a;
  b.center = {0, -3.5, 0};
  SatResult3 r = collideObb3(a, b);
  EXPECT_FALSE(r.hit);
  EXPECT_DOUBLE_EQ(r.separation, 1.5);
  EXPECT_EQ(r.axis_index, 1);
  EXPECT_EQ(r.normal, Eigen::Vector3d(0, -1, 0));
  // A turned 45 degrees about x (top edge along x), B 45 degrees about y (bottom edge along y): the
  // skew edges are closest along a_0 x b_1 = z, gap 3 - 2 sqrt 2 (exact_sat3_test checks the
  // oracle).
  const double c = std::cos(std::numbers::pi / 8), s = std::sin(std::numbers::pi / 8);
  const Obb3 ta = Obb3::fromQuaternion({0, 0, 0}, Eigen::Quaterniond(c, s, 0, 0), {2, 2, 2});
  const Obb3 tb = Obb3::fromQuaternion({0, 0, 3}, Eigen::Quaterniond(c, 0, s, 0), {2, 2, 2});
  r = collideObb3(ta, tb);
  EXPECT_FALSE(r.hit);
  EXPECT_NEAR(r.separation, 3.0 - 2.0 * std::sqrt(2.0), 1e-14);
  EXPECT_EQ(r.axis_index, 6 + 3 * 0 + 1);
  EXPECT_NEAR((r.normal - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-15);
  r = collideObb3(tb, ta);
  EXPECT_EQ(r.axis_index, 6 + 3 * 1 + 0);
  EXPECT_NEAR((r.normal + Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-15);
}

// The A-frame filter of overlapObb3 and collideObb3 (obb3.cpp) decides an edge axis only when its
// gap clears an error bound of about 1e-14 of the pair's scale, and recomputes the others
// accurately. Pairs placed on an edge axis 1e-14..1e-9 m (times the scale) from touching land
// inside and just outside that band; the verdict must be the oracle's wherever the accurate path
// is sure (|sep| above 1e-13 of the scale), near the origin and 1e7 m out.
TEST(Obb3FastPath, EdgeGapsAtTheErrorBoundMatchTheOracle) {
  for (const double offset : {0.0, 1e7}) {
    std::mt19937_64 rng(offset == 0.0 ? 0x0b3a0200 : 0x0b3a0201);
    Failures f;
    ClassStats t;
    int in_band = 0;
    int checked = 0;
    const int n = test3::scaledCount(20000);
    for (int k = 0; k < n; ++k) {
      Pair3 p{test3::randomBoxAt(rng, {offset, -offset, 0.5 * offset}),
              test3::randomBoxAt(rng, {0, 0, 0})};
      const Eigen::Vector3d axis = test3::candidateAxis(p.a, p.b, 6 + static_cast<int>(rng() % 9));
      if (axis.isZero()) continue;
      const double scale = p.a.half.sum() + p.b.half.sum();
      const double gap_sign = test3::randomSign(rng);
      const double gap = gap_sign * scale * test3::logUniform(rng, 1e-14, 1e-9);
      test3::placeAtGap(p.a, p.b, axis * test3::randomSign(rng), gap);
      const exact::ExactResult ex = exact::collideObb3(p.a, p.b);
      const double sure = 1e-13 * (scale + (p.b.center - p.a.center).lpNorm<1>());
      in_band += std::abs(ex.separation) < 1e3 * sure ? 1 : 0;
      if (!(std::abs(ex.separation) > sure)) continue;
      ++checked;
      checkPair(p, k, f, t, true, &ex);
    }
    std::printf("[ fast-path band, offset %g m ] %d checked, %d within 1e-10 of the scale\n",
                offset, checked, in_band);
    EXPECT_GT(in_band, n / 20) << "too few pairs near the filter's error bound";
    EXPECT_GT(checked, n / 2);
    EXPECT_EQ(f.count(), 0) << offset << "\n" << f.report();
  }
}

// Degenerate boxes (one, two or three half extents zero: a plate, a segment, a point) against
// random boxes and each other; strict verdicts wherever the accurate path is sure.
TEST(Obb3FastPath, DegenerateBoxesMatchTheOracle) {
  std::mt19937_64 rng(0x0b3a0202);
  Failures f;
  ClassStats t;
  const int n = test3::scaledCount(20000);
  for (int k = 0; k < n; ++k) {
    Pair3 p = test3::gapPair(rng);
    const int flat = static_cast<int>(rng() % 8);  // bit m: zero half extent m of one box
    Obb3& box = rng() % 2 == 0 ? p.a : p.b;
    for (int m = 0; m < 3; ++m) {
      if ((flat >> m) & 1) box.half[m] = 0.0;
    }
    const exact::ExactResult ex = exact::collideObb3(p.a, p.b);
    const double scale = p.a.half.sum() + p.b.half.sum() + (p.b.center - p.a.center).lpNorm<1>();
    checkPair(p, k, f, t, std::abs(ex.separation) > 1e-13 * scale, &ex);
  }
  EXPECT_EQ(f.count(), 0) << f.report();
}

// Stored matrices off a rotation by 1e-12 (the filter's bound widens with frameDefect) and by 1e-9
// (past 2^-30: the filter is off and every edge axis takes the accurate path).
TEST(Obb3FastPath, PerturbedFramesMatchTheOracle) {
  for (const double eps : {1e-12, 1e-9}) {
    std::mt19937_64 rng(eps < 1e-10 ? 0x0b3a0203 : 0x0b3a0205);
    Failures f;
    ClassStats t;
    const int n = test3::scaledCount(20000);
    for (int k = 0; k < n; ++k) {
      Pair3 p = test3::gapPair(rng);
      for (Obb3* box : {&p.a, &p.b}) {
        Eigen::Matrix3d m = box->rotation();
        for (int e = 0; e < 9; ++e) m(e / 3, e % 3) += eps * test3::uniform(rng, -1, 1);
        box->setRotation(m);
      }
      const double phi = std::max(frameDefect(p.a.rotation()), frameDefect(p.b.rotation()));
      ASSERT_GT(phi, 0.1 * eps);
      ASSERT_LT(phi, 10.0 * eps);
      // checkPair but for the unit normal: a face normal is the stored column, 1e-9 off unit.
      const exact::ExactResult ex = exact::collideObb3(p.a, p.b);
      ++t.cases;
      for (const auto& [x, y] : {std::pair{&p.a, &p.b}, std::pair{&p.b, &p.a}}) {
        const SatResult3 r = collideObb3(*x, *y);
        // Structured bindings are captured by copy: clang 14 cannot capture them by reference.
        const auto fail = [&, x = x, y = y](const std::string& what) {
          f.fail(k, what + "\n" + describe(*x, *y));
        };
        if (!(std::abs(r.separation - ex.separation) <= kSepTolerance)) fail("separation");
        if (std::abs(ex.separation) > kHitTolerance && r.hit != ex.hit) fail("hit");
        if (overlapObb3(*x, *y) != r.hit) fail("overlapObb3 disagrees");
      }
    }
    EXPECT_EQ(f.count(), 0) << eps << "\n" << f.report();
    EXPECT_EQ(t.cases, n);
  }
}

TEST(Obb3FastPath, FrameDefectOfRotationsAReflectionAndNaN) {
  std::mt19937_64 rng(0x0b3a0204);
  for (int k = 0; k < 1000; ++k) {
    const Obb3 box = Obb3::fromQuaternion({0, 0, 0}, test3::randomRotation(rng), {1, 1, 1});
    const double phi = frameDefect(box.rotation());
    ASSERT_GT(phi, 0.0);  // never below the 4 ulps of its own rounding
    ASSERT_LT(phi, 1e-14);
    ASSERT_EQ(box.frameDefect(), phi);  // the box's own copy, which the queries read
  }
  Eigen::Matrix3d reflection = Eigen::Matrix3d::Identity();
  reflection(2, 2) = -1.0;  // orthonormal but left-handed
  EXPECT_GE(frameDefect(reflection), 2.0);
  Eigen::Matrix3d nan = Eigen::Matrix3d::Identity();
  nan(1, 0) = std::nan("");
  EXPECT_EQ(frameDefect(nan), std::numeric_limits<double>::infinity());
  nan(1, 0) = std::numeric_limits<double>::infinity();
  EXPECT_EQ(frameDefect(nan), std::numeric_limits<double>::infinity());
}

// The queries read the defect the box stores, so every way of setting the rotation must keep it
// equal to frameDefect(rotation()): the default identity, setRotation, and a copy.
TEST(Obb3FastPath, BoxStoresTheDefectOfItsRotation) {
  Obb3 box;
  EXPECT_EQ(box.frameDefect(), frameDefect(box.rotation()));
  Eigen::Matrix3d m = Eigen::Matrix3d::Identity();
  m(0, 1) = 1e-9;
  box.setRotation(m);
  EXPECT_EQ(box.rotation(), m);
  EXPECT_EQ(box.frameDefect(), frameDefect(m));
  EXPECT_GT(box.frameDefect(), 1e-10);
  const Obb3 copy = box;
  EXPECT_EQ(copy.frameDefect(), frameDefect(m));
  m(1, 0) = std::nan("");
  box.setRotation(m);
  EXPECT_EQ(box.frameDefect(), std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace cardemo
