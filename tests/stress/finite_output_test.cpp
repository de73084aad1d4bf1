// No NaN or infinity ever leaves the geometry for finite input: every query over seeded random
// boxes and polygons whose coordinates and sizes range over the whole finite double range (down
// to the smallest normal number, up to the largest finite one), mixed in one call.

#include <gtest/gtest.h>

#include <array>
#include <cfloat>
#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "../geometry/random_cases2.hpp"
#include "compare/exact/exact_sat.hpp"
#include "extremes.hpp"
#include "geometry/angle.hpp"
#include "geometry/convex_polygon.hpp"
#include "geometry/finite.hpp"
#include "geometry/obb2.hpp"
#include "geometry/obb3.hpp"
#include "geometry/sat_obb2.hpp"
#include "stress_scale.hpp"

namespace cardemo::stress {
namespace {

using testing::Extremes;

std::string text(const Obb2& b) {
  std::ostringstream s;
  s.precision(17);
  s << "{c " << b.center.transpose() << ", axis " << b.axis.transpose() << ", half "
    << b.half.transpose() << "}";
  return s.str();
}

bool finite(const SatResult2& r) {
  return std::isfinite(r.separation) && r.normal.allFinite();
}

TEST(FiniteOutput, Boxes2d) {
  Extremes x(0xf1a1);
  const std::int64_t n = scaled(200000);
  int failures = 0;
  for (std::int64_t k = 0; k < n && failures < 5; ++k) {
    const Obb2 a = x.box();
    const Obb2 b = x.boxNear(a);
    const SatResult2 r = collideObb2(a, b);
    bool ok = finite(r) && r.hit == (r.separation <= 0.0) && a.aabb().min.allFinite() &&
              a.aabb().max.allFinite();
    for (const Eigen::Vector2d& c : a.corners()) ok = ok && c.allFinite();
    if (!ok) {
      ++failures;
      ADD_FAILURE() << "case " << k << ": sep " << r.separation << " normal "
                    << r.normal.transpose() << "\nA " << text(a) << "\nB " << text(b);
    }
  }
}

TEST(FiniteOutput, Polygons) {
  Extremes x(0xf1a2);
  const std::int64_t n = scaled(50000);
  int failures = 0, accepted = 0;
  for (std::int64_t k = 0; k < n && failures < 5; ++k) {
    const Obb2 box = x.box();
    const Eigen::Vector2d u = x.unit();
    const std::optional<ConvexPolygon> p = x.polygon(box.center + u * x.size());
    const std::optional<ConvexPolygon> q = x.polygon(x.pick(2) == 0 ? box.center : x.point());
    if (!p || !q) continue;
    ++accepted;
    const SatResult2 results[4] = {collidePolygons(*p, *q), collidePolygons(*q, *p),
                                   collideObbPolygon(box, *p), collidePolygonObb(*p, box)};
    bool ok = p->aabb().min.allFinite() && p->aabb().max.allFinite() && p->centroid().allFinite();
    for (const SatResult2& r : results) ok = ok && finite(r) && r.hit == (r.separation <= 0.0);
    if (!ok) {
      ++failures;
      ADD_FAILURE() << "case " << k << ": polygons " << p->vertex(0).transpose() << " / "
                    << q->vertex(0).transpose() << " box " << text(box);
    }
  }
  std::printf("[ finite polygons ] %d of %lld polygon pairs accepted by fromPoints\n", accepted,
              static_cast<long long>(n));
  EXPECT_GT(accepted, n / 20);
}

ConvexPolygon scaledBy(ConvexPolygon p, int k) {
  for (int i = 0; i < p.count; ++i) {
    Eigen::Vector2d& v = p.vertices[static_cast<std::size_t>(i)];
    v = {std::scalbn(v.x(), k), std::scalbn(v.y(), k)};
  }
  return p;
}

// Polygons brought to 2^600 (~4e180: the projections overflow) or 2^-600 (~2e-181: the squared
// edge lengths underflow) take the rescaled path, which must give exactly 2^k times the answer at
// unit scale, which the exact oracle checks.
TEST(FiniteOutput, PolygonsScaleExactlyByPowersOfTwo) {
  testing::Random rng(0xf1a5);
  const int n = static_cast<int>(scaled(5000));
  for (int i = 0; i < n; ++i) {
    const ConvexPolygon a = rng.polygon(rng.offset(0.0, 10.0), 0.01, 10.0);
    const ConvexPolygon b = rng.polygon(rng.offset(0.0, 10.0), 0.01, 10.0);
    const SatResult2 unit = collidePolygons(a, b);
    const exact::ExactResult ex = exact::collidePolygons(a, b);
    ASSERT_NEAR(unit.separation, ex.separation, testing::kSepTolerance) << i;
    for (const int k : {600, -600, 900, -1000}) {
      const SatResult2 r = collidePolygons(scaledBy(a, k), scaledBy(b, k));
      ASSERT_EQ(r.separation, std::scalbn(unit.separation, k)) << i << " at 2^" << k;
      ASSERT_EQ(r.normal, unit.normal) << i << " at 2^" << k;
      ASSERT_EQ(r.hit, unit.hit) << i << " at 2^" << k;
    }
  }
}

TEST(FiniteOutput, Boxes3d) {
  Extremes x(0xf1a3);
  const std::int64_t n = scaled(100000);
  int failures = 0;
  for (std::int64_t k = 0; k < n && failures < 5; ++k) {
    const Obb3 a = x.box3();
    Obb3 b = x.box3();
    if (x.pick(2) == 0) {
      b.center = a.center + Eigen::Vector3d(x.coordinate(), 0, 0);
      const double c = b.center.cwiseAbs().maxCoeff(), room = kMaxCoordinate - b.half.sum();
      if (c > room) b.center *= 0.999 * room / c;
    }
    const bool inputs_ok = a.rotation().allFinite() && b.rotation().allFinite() &&
                           a.aabb().min.allFinite() && a.aabb().max.allFinite();
    const SatResult3 r = collideObb3(a, b);
    const bool ok = inputs_ok && std::isfinite(r.separation) && r.normal.allFinite() &&
                    r.hit == (r.separation <= 0.0);
    if (!ok) {
      ++failures;
      std::ostringstream s;
      s.precision(17);
      s << "case " << k << ": sep " << r.separation << " normal " << r.normal.transpose()
        << "\nA c " << a.center.transpose() << " h " << a.half.transpose() << "\nB c "
        << b.center.transpose() << " h " << b.half.transpose();
      ADD_FAILURE() << s.str();
    }
  }
}

TEST(FiniteOutput, Angles) {
  Extremes x(0xf1a4);
  for (int k = 0; k < 100000; ++k) {
    const double v = x.coordinate();
    const Eigen::Vector2d d = unitFromDegrees(v), r = unitFromRadians(v);
    ASSERT_TRUE(d.allFinite() && std::abs(d.norm() - 1.0) <= 4e-16) << v;
    ASSERT_TRUE(r.allFinite() && std::abs(r.norm() - 1.0) <= 4e-16) << v;
    const double w = wrapRadians(v);
    ASSERT_TRUE(w > -3.14159265358979324 && w <= 3.14159265358979324) << v;
    const double deg = degreesOf(x.point());
    ASSERT_TRUE(deg > -180.0 && deg <= 180.0) << deg;
  }
}

}  // namespace
}  // namespace cardemo::stress
