#include "geometry/sat_obb2.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>

#include "compare/exact/exact_sat.hpp"
#include "geometry/angle.hpp"
#include "random_cases2.hpp"

namespace cardemo {
namespace {

using testing::ClassStats;
using testing::Failures;
using testing::Random;

using BoxPairMaker = std::function<std::pair<Obb2, Obb2>(Random&)>;

Obb2 moved(Obb2 b, const Eigen::Vector2d& by) {
  b.center += by;
  return b;
}

// Compares collideObb2/overlapObb2 in both orders with the exact oracle over one class of pairs.
ClassStats runBoxClass(std::uint64_t seed, const BoxPairMaker& make) {
  return testing::runPairClass(
      seed, make, [](const Obb2& a, const Obb2& b, int i, Failures& f, ClassStats& stats) {
        const exact::ExactResult ex = exact::collideObb2(a, b);
        const SatResult2 ab = collideObb2(a, b);
        const SatResult2 ba = collideObb2(b, a);
        const auto ca = a.corners(), cb = b.corners();
        testing::checkAgainstExact(ab, ex.hit, ex.separation, ca, cb, a.center, i, f, stats);
        testing::checkAgainstExact(ba, ex.hit, ex.separation, cb, ca, a.center, i, f, stats);
        f.check(overlapObb2(a, b) == ab.hit && overlapObb2(b, a) == ba.hit, i,
                "overlapObb2 differs");
        const double asym = std::abs(ab.separation - ba.separation);
        stats.noteAsymmetry(asym);
        f.check(asym <= 1e-9, i, "sep not symmetric");
        // The normal flips: -n(B,A) realises the same separation for (A, B).
        f.check(std::abs(testing::signedGap(ca, cb, -ba.normal, a.center) - ab.separation) <=
                    testing::kSepTolerance,
                i, "reversed normal does not realise sep");
        if (i % 10 == 0) {
          // Moving B along the normal by -sep plus a margin leaves a gap on that axis: exactly
          // apart.
          const double margin = 1e-5;
          const Obb2 apart = moved(b, ab.normal * (margin - ab.separation));
          f.check(!exact::collideObb2(a, apart).hit, i,
                  "moving B out along the normal did not separate");
        }
        if (i % 100 == 0) {
          const exact::ExactResult rev = exact::collideObb2(b, a);
          f.check(rev.hit == ex.hit && rev.separation == ex.separation, i, "oracle not symmetric");
        }
        return ex;
      });
}

// Lateral offset (along `lateral`) of the box's support point in direction `d`, from its centre.
double supportLateral(const Obb2& box, const Eigen::Vector2d& d, const Eigen::Vector2d& lateral) {
  const auto corners = box.corners();
  int best = 0;
  for (int i = 1; i < 4; ++i) {
    if (corners[i].dot(d) > corners[best].dot(d)) best = i;
  }
  return (corners[best] - box.center).dot(lateral);
}

// B placed against one face of A (or A against one of B's faces) with a chosen signed gap; the
// other box's nearest corner lands on that face, so the gap is usually the SAT separation.
std::pair<Obb2, Obb2> nearTouching(Random& rng, const Eigen::Vector2d& base, double gap,
                                   Obb2 b_shape) {
  Obb2 a = rng.box(base, 0.1, 20.0);
  a.center = base;
  Obb2& b = b_shape;
  const bool along_a = rng.integer(0, 1) == 0;
  const Obb2& owner = along_a ? a : b;
  const bool use_x = rng.integer(0, 1) == 0;
  const Eigen::Vector2d d = (use_x ? owner.axis : owner.perp()) * rng.sign();
  const Eigen::Vector2d lateral{-d.y(), d.x()};
  const double reach = testing::supportRadius(a, d) + testing::supportRadius(b, d);
  const double face = 0.9 * testing::supportRadius(owner, lateral);
  const double on_face = rng.uniform(-face, face);
  // Lateral position of B's centre relative to A's so that the non-owner's corner meets the face.
  const double side =
      along_a ? on_face - supportLateral(b, -d, lateral) : supportLateral(a, d, lateral) - on_face;
  b.center = a.center + d * (reach + gap) + lateral * side;
  return {a, b};
}

std::pair<Obb2, Obb2> randomPlacement(Random& rng, const Obb2& a, Obb2 b) {
  const double reach = a.half.norm() + b.half.norm();
  b.center = a.center + rng.offset(0.0, 1.2 * reach);
  return {a, b};
}

TEST(SatObb2Random, GapsOnBothSidesOfTouching) {
  int on_target = 0;
  int total = 0;
  const ClassStats s = runBoxClass(1001, [&](Random& rng) {
    const double gap = rng.signedLogUniform(1e-9, 1.0);
    const Eigen::Vector2d base = rng.offset(0, 50);
    const Obb2 b = rng.box(Eigen::Vector2d::Zero(), 0.1, 20.0);
    auto pair = nearTouching(rng, base, gap, b);
    // The oracle, not the construction, is the reference; sample how often it lands on target.
    if (total++ % 10 == 0) {
      const double ex = exact::collideObb2(pair.first, pair.second).separation;
      on_target += std::abs(ex - gap) <= 1e-12 + 1e-6 * std::abs(gap) ? 1 : 0;
    }
    return pair;
  });
  EXPECT_GT(on_target, 8 * (total / 10) / 10)
      << "the construction should mostly realise the chosen gap";
  EXPECT_GT(s.exact_hits, s.cases / 4);
  EXPECT_LT(s.exact_hits, 3 * s.cases / 4);
}

TEST(SatObb2Random, FarFromOrigin) {
  const ClassStats s = runBoxClass(1002, [](Random& rng) {
    const Eigen::Vector2d base = rng.farPoint(1e7);
    if (rng.integer(0, 1) == 0) {
      const double gap = rng.signedLogUniform(1e-9, 1.0);
      return nearTouching(rng, base, gap, rng.box(Eigen::Vector2d::Zero(), 0.1, 20.0));
    }
    const Obb2 a = rng.box(base, 0.1, 20.0);
    const Obb2 b = rng.box(base, 0.1, 20.0);
    return randomPlacement(rng, a, b);
  });
  EXPECT_GT(s.exact_hits, s.cases / 10);
}

TEST(SatObb2Random, ExtremeSizesAndAspectRatios) {
  const ClassStats s = runBoxClass(1003, [](Random& rng) {
    const Eigen::Vector2d base = rng.offset(0, 1000);
    Obb2 a = rng.extremeBox(base), b = rng.extremeBox(base);
    if (rng.integer(0, 1) == 0) {
      const Eigen::Vector2d face = rng.integer(0, 1) == 0 ? a.axis : a.perp();
      const Eigen::Vector2d d = face * rng.sign();
      const double reach = testing::supportRadius(a, d) + testing::supportRadius(b, d);
      b.center = a.center + d * (reach + rng.signedLogUniform(1e-9, 1.0));
      return std::pair{a, b};
    }
    return randomPlacement(rng, a, b);
  });
  EXPECT_GT(s.exact_hits, s.cases / 10);
}

TEST(SatObb2Random, NearParallel) {
  const ClassStats s = runBoxClass(1004, [](Random& rng) {
    Obb2 b = rng.box(Eigen::Vector2d::Zero(), 0.1, 100.0);
    const Eigen::Vector2d base = rng.offset(0, 1e4);
    const double gap = rng.signedLogUniform(1e-9, 1.0);
    auto pair = nearTouching(rng, base, gap, b);
    // Turn B to within 1e-15..1e-3 rad of A's heading (plus a multiple of 90 degrees).
    const int quarters = rng.integer(0, 3);
    const double heading = std::atan2(pair.first.axis.y(), pair.first.axis.x()) +
                           quarters * 0.5 * std::numbers::pi + rng.signedLogUniform(1e-15, 1e-3);
    pair.second.axis = unitFromRadians(heading);
    return pair;
  });
  EXPECT_GT(s.exact_hits, s.cases / 10);
  EXPECT_LT(s.exact_hits, 9 * s.cases / 10);
}

TEST(SatObb2Random, Containment) {
  const ClassStats s = runBoxClass(1005, [](Random& rng) {
    const Eigen::Vector2d base = rng.farPoint(1e7);
    const Obb2 a = rng.box(base, 1.0, 100.0);
    Obb2 b = rng.box(Eigen::Vector2d::Zero(), 0.01, 0.5 * std::min(a.half.x(), a.half.y()));
    // Room left for B's centre inside A along each of A's axes.
    const double rx = a.half.x() - testing::supportRadius(b, a.axis);
    const double ry = a.half.y() - testing::supportRadius(b, a.perp());
    const double along = rng.uniform(-0.99, 0.99);
    const double across = rng.uniform(-0.99, 0.99);
    b.center = a.center + a.axis * along * rx + a.perp() * across * ry;
    return std::pair{a, b};
  });
  EXPECT_EQ(s.exact_hits, s.cases) << "every contained pair overlaps";
}

// Axis-aligned boxes on a 1/8 m grid touching along an edge or at a corner: exact in double.
TEST(SatObb2Random, ExactTouching) {
  const ClassStats s = runBoxClass(1006, [](Random& rng) {
    const auto grid = [&](int lo, int hi) { return rng.integer(lo, hi) / 8.0; };
    const auto coordinate = [&] {
      const double whole = std::round(rng.uniform(-1e7, 1e7));
      return whole + grid(0, 7);
    };
    const auto gridBox = [&](const Eigen::Vector2d& center) {
      const double heading = 90.0 * rng.integer(0, 3);
      const double length = grid(1, 800);
      const double width = grid(1, 800);
      return Obb2::fromDegrees(center, heading, length, width);
    };
    const Eigen::Vector2d base{coordinate(), coordinate()};
    const Obb2 a = gridBox(base);
    Obb2 b = gridBox(Eigen::Vector2d::Zero());
    const Eigen::Vector2d ea = a.aabb().size() / 2, eb = b.aabb().size() / 2;
    const int k = rng.integer(0, 1);
    const int l = 1 - k;
    Eigen::Vector2d offset;
    offset[k] = rng.sign() * (ea[k] + eb[k]);
    const int reach = static_cast<int>(8 * (ea[l] + eb[l]));
    offset[l] = rng.integer(-reach, reach) / 8.0;  // the ends give corner-to-corner contact
    b.center = a.center + offset;
    return std::pair{a, b};
  });
  EXPECT_EQ(s.exact_hits, s.cases) << "exact touching counts as a hit";
}

void expectTouching(const Obb2& a, const Obb2& b) {
  const exact::ExactResult ex = exact::collideObb2(a, b);
  EXPECT_TRUE(ex.hit);
  EXPECT_EQ(ex.separation, 0.0);
  for (const auto& [p, q] : {std::pair{a, b}, std::pair{b, a}}) {
    const SatResult2 r = collideObb2(p, q);
    EXPECT_TRUE(r.hit);
    EXPECT_TRUE(overlapObb2(p, q));
    EXPECT_EQ(r.separation, 0.0);
  }
}

TEST(SatObb2Touching, SharedEdgeAtEveryRightAngle) {
  for (int heading : {0, 90, 180, 270}) {
    SCOPED_TRACE(heading);
    const Obb2 a = Obb2::fromDegrees({0, 0}, heading, 4.5, 1.8);
    const Obb2 b = Obb2::fromDegrees(a.center + a.axis * 4.5, heading + 180, 4.5, 1.8);
    expectTouching(a, b);
    const Obb2 side = Obb2::fromDegrees(a.center + a.perp() * 1.8, heading, 4.5, 1.8);
    expectTouching(a, side);
  }
}

TEST(SatObb2Touching, SharedCorner) {
  const Obb2 a = Obb2::fromDegrees({10, 5}, 0, 4, 2);
  const Obb2 b = Obb2::fromDegrees({14, 7}, 90, 2, 4);
  expectTouching(a, b);
}

TEST(SatObb2Touching, FarFromOrigin) {
  const Obb2 a = Obb2::fromDegrees({1e7, -1e7}, 90, 4.5, 1.75);
  const Obb2 b = Obb2::fromDegrees({1e7 + 1.75, -1e7 + 1.0}, 270, 4.5, 1.75);
  expectTouching(a, b);
}

TEST(SatObb2Named, SeparatedNormalPointsFromAToB) {
  const Obb2 a = Obb2::fromDegrees({0, 0}, 0, 2, 2);
  const Obb2 b = Obb2::fromDegrees({-5, 0.5}, 0, 2, 2);
  const SatResult2 r = collideObb2(a, b);
  EXPECT_FALSE(r.hit);
  EXPECT_DOUBLE_EQ(r.separation, 3.0);
  EXPECT_EQ(r.normal, Eigen::Vector2d(-1, 0));
  EXPECT_EQ(collideObb2(b, a).normal, Eigen::Vector2d(1, 0));
}

TEST(SatObb2Named, PenetrationDepth) {
  const Obb2 a = Obb2::fromDegrees({0, 0}, 0, 2, 2);
  const Obb2 b = Obb2::fromDegrees({0.25, 1.5}, 0, 2, 2);
  const SatResult2 r = collideObb2(a, b);
  EXPECT_TRUE(r.hit);
  EXPECT_DOUBLE_EQ(r.separation, -0.5);
  EXPECT_EQ(r.normal, Eigen::Vector2d(0, 1));
}

}  // namespace
}  // namespace cardemo
