// Degenerate geometry against the exact GMP oracle, beyond what tests/geometry covers (1 cm to
// 100 m): 2D boxes from 1 mm to 1 km with aspect ratios up to 1e4, slivers of polygons, exact
// touching along shared edges and at shared corners at every size and far out; 3D boxes from
// 1 mm to 1 km with parallel and near-parallel edges (1e-15 to 1e-3 rad) and exactly coincident
// boxes. Generators are tests/geometry's random_cases2/3, scaled.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>

#include "../geometry/random_cases2.hpp"
#include "../geometry/random_cases3.hpp"
#include "compare/exact/exact_sat.hpp"
#include "geometry/convex_polygon.hpp"
#include "geometry/obb3.hpp"
#include "geometry/sat_obb2.hpp"
#include "stress_scale.hpp"

namespace cardemo::stress {
namespace {

using cardemo::testing::ClassStats;
using cardemo::testing::Failures;
using cardemo::testing::Random;

// A box with sides log-uniform in 1 mm..1 km and aspect ratio up to 1e4.
Obb2 wideRangeBox(Random& rng, const Eigen::Vector2d& center) {
  const double length = rng.logUniform(1e-3, 1e3);
  const double aspect = rng.logUniform(1.0, std::min(1e4, length / 1e-3));
  Eigen::Vector2d half{0.5 * length, 0.5 * length / aspect};
  if (rng.integer(0, 1) == 1) std::swap(half.x(), half.y());
  return {center, rng.direction(), half};
}

void report(const char* name, const Failures& f, const ClassStats& s) {
  testing::printClassStats(name, s);
  EXPECT_EQ(f.count(), 0) << name << "\n" << f.report();
}

// Both argument orders against the oracle (random_cases2's checks: hit, sep, unit normal that
// realises sep).
void checkBoxes(const Obb2& a, const Obb2& b, int i, Failures& f, ClassStats& s) {
  const exact::ExactResult ex = exact::collideObb2(a, b);
  const auto ca = a.corners(), cb = b.corners();
  testing::checkAgainstExact(collideObb2(a, b), ex.hit, ex.separation, ca, cb, a.center, i, f, s);
  testing::checkAgainstExact(collideObb2(b, a), ex.hit, ex.separation, cb, ca, a.center, i, f, s);
  f.check(overlapObb2(a, b) == collideObb2(a, b).hit, i, "overlapObb2 differs");
  s.tally(ex.hit, ex.separation);
}

TEST(Degenerate2d, BoxesFromAMillimetreToAKilometre) {
  Random rng(0xde01);
  Failures f;
  ClassStats s;
  const int n = static_cast<int>(scaled(10000));
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d base = rng.farPoint(1e7);
    const Obb2 a = wideRangeBox(rng, base);
    Obb2 b = wideRangeBox(rng, base);
    // Against one of A's faces at a gap of 1e-9..1 m either side, or anywhere near A.
    const Eigen::Vector2d face = rng.integer(0, 1) == 0 ? a.axis : a.perp();
    const Eigen::Vector2d d = face * rng.sign();
    const double reach = testing::supportRadius(a, d) + testing::supportRadius(b, d);
    b.center = rng.integer(0, 2) != 0
                   ? Eigen::Vector2d(a.center + d * (reach + rng.signedLogUniform(1e-9, 1.0)))
                   : Eigen::Vector2d(a.center + rng.offset(0.0, 1.2 * reach));
    checkBoxes(a, b, i, f, s);
  }
  report("2D boxes 1 mm..1 km, aspect <= 1e4, to 1e7 m", f, s);
  EXPECT_GT(s.exact_hits, n / 10);
}

TEST(Degenerate2d, NearParallelAtEverySize) {
  Random rng(0xde02);
  Failures f;
  ClassStats s;
  const int n = static_cast<int>(scaled(10000));
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d base = rng.farPoint(1e7);
    const Obb2 a = wideRangeBox(rng, base);
    Obb2 b = wideRangeBox(rng, base);
    // B turned to within 1e-15..1e-3 rad of A (plus a quarter turn), then placed against A's face.
    const int quarters = rng.integer(0, 3);
    const double turn = quarters * 0.5 * std::numbers::pi + rng.signedLogUniform(1e-15, 1e-3);
    b.axis = {a.axis.x() * std::cos(turn) - a.axis.y() * std::sin(turn),
              a.axis.y() * std::cos(turn) + a.axis.x() * std::sin(turn)};
    b.axis.normalize();
    const Eigen::Vector2d face = rng.integer(0, 1) == 0 ? a.axis : a.perp();
    const Eigen::Vector2d d = face * rng.sign();
    const double reach = testing::supportRadius(a, d) + testing::supportRadius(b, d);
    const double gap = rng.signedLogUniform(1e-9, 1e-3);
    const double shift = rng.uniform(-1.0, 1.0);
    b.center =
        a.center + d * (reach + gap) + Eigen::Vector2d(-d.y(), d.x()) * shift * a.half.minCoeff();
    checkBoxes(a, b, i, f, s);
  }
  report("2D near-parallel 1e-15..1e-3 rad, 1 mm..1 km", f, s);
  EXPECT_GT(s.exact_hits, n / 10);
}

// Axis-aligned boxes on a 2^-10 m grid (about 1 mm) with sides up to 2^10 m (about 1 km),
// touching exactly along a shared edge or at a shared corner, near the origin or around 2^22 m
// (4e6 m: every coordinate stays exact). Touching is contact: separation exactly 0, a hit.
TEST(Degenerate2d, ExactTouchingSharedEdgesAndCorners) {
  Random rng(0xde03);
  Failures f;
  ClassStats s;
  const int n = static_cast<int>(scaled(10000));
  int corners = 0;
  for (int i = 0; i < n; ++i) {
    const auto grid = [&](double lo, double hi) {
      return std::ldexp(std::round(std::ldexp(rng.uniform(lo, hi), 10)), -10);
    };
    const auto side = [&] { return std::max(std::ldexp(1.0, -10), grid(0.0, 1024.0)); };
    const auto gridBox = [&](const Eigen::Vector2d& center) {
      const double heading = 90.0 * rng.integer(0, 3);
      const double length = side();
      const double width = side();
      return Obb2::fromDegrees(center, heading, length, width);
    };
    const double far = rng.integer(0, 1) == 0 ? 0.0 : 4194304.0;
    const auto coordinate = [&] {
      const double sign = rng.sign();
      return sign * far + grid(-8, 8);
    };
    const Eigen::Vector2d base{coordinate(), coordinate()};
    const Obb2 a = gridBox(base);
    Obb2 b = gridBox({0, 0});
    const Eigen::Vector2d ea = a.aabb().size() / 2, eb = b.aabb().size() / 2;
    const int k = rng.integer(0, 1), l = 1 - k;
    Eigen::Vector2d offset;
    offset[k] = rng.sign() * (ea[k] + eb[k]);
    const bool corner = rng.integer(0, 3) == 0;
    offset[l] = corner ? rng.sign() * (ea[l] + eb[l]) : grid(-1.0, 1.0) * (ea[l] + eb[l]);
    corners += corner ? 1 : 0;
    b.center = a.center + offset;
    checkBoxes(a, b, i, f, s);
    f.check(collideObb2(a, b).separation == 0.0 && collideObb2(b, a).separation == 0.0, i,
            "touching boxes must give separation exactly 0");
    // The same contact against B as an obstacle polygon (its exact corners).
    const ConvexPolygon pb = ConvexPolygon::fromObb(b);
    const SatResult2 r = collideObbPolygon(a, pb);
    f.check(r.hit && r.separation == 0.0, i,
            "box against touching polygon: sep " + std::to_string(r.separation));
    f.check(exact::collidePolygons(ConvexPolygon::fromObb(a), pb).hit, i, "oracle: not touching");
  }
  report("2D exact touching, shared edges and corners, 1 mm..1 km", f, s);
  EXPECT_EQ(s.exact_hits, s.cases);
  EXPECT_GT(corners, n / 8);
}

TEST(Degenerate2d, SliverPolygons) {
  Random rng(0xde04);
  Failures f;
  ClassStats s;
  const int n = static_cast<int>(scaled(4000));
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d base = rng.farPoint(1e7);
    // Ellipse polygons with radii 1 mm..1 km independently: aspect ratios up to 1e6 (fromPoints
    // rejects the ones it cannot tell from collinear).
    const ConvexPolygon a = rng.polygon(base, 1e-3, 1e3);
    const ConvexPolygon shape = rng.polygon(Eigen::Vector2d::Zero(), 1e-3, 1e3);
    const Eigen::Vector2d direction = rng.direction();
    const ConvexPolygon b =
        cardemo::testing::translated(shape, base + direction * rng.logUniform(1e-3, 2e3));
    const exact::ExactResult ex = exact::collidePolygons(a, b);
    const auto pa = cardemo::testing::pointsOf(a), pb = cardemo::testing::pointsOf(b);
    cardemo::testing::checkAgainstExact(collidePolygons(a, b), ex.hit, ex.separation, pa, pb,
                                        a.vertex(0), i, f, s);
    cardemo::testing::checkAgainstExact(collidePolygons(b, a), ex.hit, ex.separation, pb, pa,
                                        a.vertex(0), i, f, s);
    ++s.cases;
    s.exact_hits += ex.hit ? 1 : 0;
  }
  report("2D sliver polygons 1 mm..1 km", f, s);
  EXPECT_GT(s.exact_hits, n / 20);
}

// 3D: a tests/geometry generator's pair scaled about A's centre by 1/10..10 (sizes 1 mm..1 km),
// against the oracle in both orders; stops after 5 failures.
void run3d(const char* name, std::uint64_t seed,
           const std::function<test3::Pair3(std::mt19937_64&)>& make, int count) {
  std::mt19937_64 rng(seed);
  Failures f;
  ClassStats s;
  const int n = static_cast<int>(scaled(count));
  for (int i = 0; i < n && f.count() < 5; ++i) {
    test3::Pair3 p = make(rng);
    const double k = test3::logUniform(rng, 0.1, 10.0);
    p.b.center = p.a.center + (p.b.center - p.a.center) * k;
    p.a.half *= k;
    p.b.half *= k;
    const exact::ExactResult ex = exact::collideObb3(p.a, p.b);
    s.tally(ex.hit, ex.separation);
    for (const auto& [x, y] : {std::pair{&p.a, &p.b}, std::pair{&p.b, &p.a}}) {
      const SatResult3 r = collideObb3(*x, *y);
      s.countAxis(r.axis_index >= 6);
      const double err = std::abs(r.separation - ex.separation);
      s.max_error = std::max(s.max_error, err);
      const bool hit_ok = std::abs(ex.separation) <= testing::kHitTolerance || r.hit == ex.hit;
      // Never a false "separated" for boxes that truly touch or overlap, at any distance.
      const bool no_false_gap = !ex.hit || r.hit;
      if (!(err <= testing::kSepTolerance) || !hit_ok || !no_false_gap ||
          overlapObb3(*x, *y) != r.hit) {
        std::ostringstream m;
        m.precision(17);
        m << "sep " << r.separation << " exact " << ex.separation << " hit " << r.hit
          << " exact hit " << ex.hit << " axis " << r.axis_index;
        f.fail(i, m.str());
      }
    }
  }
  report(name, f, s);
}

TEST(Degenerate3d, NearParallelEdgesAtEverySize) {
  for (const double angle : {1e-15, 1e-12, 1e-9, 1e-6, 1e-3}) {
    char name[64];
    std::snprintf(name, sizeof name, "3D near-parallel %g rad, 1 mm..1 km", angle);
    run3d(
        name, 0xde10 + static_cast<std::uint64_t>(-std::log10(angle)),
        [angle](std::mt19937_64& rng) { return test3::nearParallelPair(rng, angle, angle); }, 1000);
  }
}

TEST(Degenerate3d, ExactlyParallelAtEverySize) {
  run3d("3D exactly parallel, 1 mm..1 km", 0xde20, test3::parallelPair, 5000);
}

TEST(Degenerate3d, ExactlyCoincidentAtEverySize) {
  run3d("3D exactly coincident, 1 mm..1 km", 0xde21, test3::coincidentPair, 5000);
}

}  // namespace
}  // namespace cardemo::stress
