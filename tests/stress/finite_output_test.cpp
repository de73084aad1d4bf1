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
#include "geometry/angle.hpp"
#include "geometry/convex_polygon.hpp"
#include "geometry/finite.hpp"
#include "geometry/obb2.hpp"
#include "geometry/obb3.hpp"
#include "geometry/sat_obb2.hpp"
#include "lab/kernels/manifold2.hpp"
#include "stress_scale.hpp"

namespace cardemo::stress {
namespace {

// Magnitudes that stress overflow (sums and products of huge values), underflow (squares of tiny
// values) and cancellation (huge coordinates, tiny sizes).
// The largest sizes and coordinates are 1e300 so that the sum of a box's centre and extents is
// representable (a box reaching beyond DBL_MAX has no finite corners).
constexpr std::array<double, 12> kMagnitudes{0.0, DBL_MIN, 1e-300, 1e-160, 1e-15, 1e-3,
                                             1.0, 1e3,     1e7,    1e15,   1e160, 1e300};

class Extremes {
 public:
  explicit Extremes(std::uint64_t seed) : rng_(seed) {}
  double magnitude() {
    const double m = kMagnitudes[pick(kMagnitudes.size())];
    // Sometimes a value next to the chosen one, so not everything is a round number.
    return pick(2) == 0 ? m : m * std::uniform_real_distribution<double>(0.5, 1.0)(rng_);
  }
  double coordinate() { return pick(2) == 0 ? magnitude() : -magnitude(); }
  // Sizes up to a quarter of the domain, so that a centre can always be fitted in beside them.
  double size() {
    const double s = 0.25 * magnitude();
    return s > 0.0 ? s : DBL_MIN;
  }
  Eigen::Vector2d point() { return {coordinate(), coordinate()}; }
  Eigen::Vector2d unit() {
    if (pick(4) == 0) return unitFromDegrees(90.0 * static_cast<double>(pick(4)));
    return unitFromRadians(std::uniform_real_distribution<double>(-4.0, 4.0)(rng_));
  }
  Obb2 box() { return fitted({point(), unit(), {size(), size()}}); }
  // A box near another (so that the pair is close to touching at its scale).
  Obb2 boxNear(const Obb2& other) {
    Obb2 b = box();
    if (pick(2) == 0) {
      const Eigen::Vector2d u = unit();
      b.center = other.center + u * size();
    }
    return fitted(b);
  }
  // The box with its centre pulled in so that it lies within kMaxCoordinate (inDomain).
  static Obb2 fitted(Obb2 b) {
    const double room = kMaxCoordinate - b.half.x() - b.half.y();
    const double c = b.center.cwiseAbs().maxCoeff();
    if (c > room) b.center *= 0.999 * room / c;
    return b;
  }
  // A polygon accepted by fromPoints: points on an ellipse of extreme size around an extreme
  // centre; nullopt when the points are too degenerate for fromPoints.
  std::optional<ConvexPolygon> polygon(const Eigen::Vector2d& center) {
    const int n = 3 + static_cast<int>(pick(14));
    // Sizes below ~1e-9 of the centre's magnitude round the points together: fromPoints would
    // reject nearly all of them.
    const double floor = 1e-9 * center.cwiseAbs().maxCoeff();
    const double rx = std::max(size(), floor), ry = std::max(size(), floor);
    if (center.cwiseAbs().maxCoeff() + rx + ry > kMaxCoordinate) return std::nullopt;
    std::vector<Eigen::Vector2d> points;
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector2d u = unitFromDegrees(360.0 * i / n + 1.0);
      points.push_back(center + Eigen::Vector2d(rx * u.x(), ry * u.y()));
    }
    return ConvexPolygon::fromPoints(points);
  }
  Eigen::Quaterniond quaternion() {
    std::normal_distribution<double> g;
    const double s = magnitude();
    Eigen::Quaterniond q{g(rng_), g(rng_), g(rng_), g(rng_)};
    q.coeffs() *= s > 0.0 ? s : 1.0;
    if (!q.coeffs().allFinite() || q.coeffs().cwiseAbs().maxCoeff() == 0.0) q = {1, 0, 0, 0};
    return q;
  }
  Obb3 box3() {
    const Eigen::Vector3d center{coordinate(), coordinate(), coordinate()};
    const Eigen::Quaterniond q = quaternion();
    const Eigen::Vector3d sizes{size(), size(), size()};
    Obb3 b = Obb3::fromQuaternion(center, q, sizes);
    const double room = kMaxCoordinate - b.half.sum();
    const double c = b.center.cwiseAbs().maxCoeff();
    if (c > room) b.center *= 0.999 * room / c;
    return b;
  }
  std::size_t pick(std::size_t n) {
    return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng_);
  }

 private:
  std::mt19937_64 rng_;
};

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
    const bool ok = finite(r) && r.hit == (r.separation <= 0.0) && a.aabb().min.allFinite() &&
                    a.aabb().max.allFinite() && a.rotationProofAabb().min.allFinite() &&
                    a.rotationProofAabb().max.allFinite();
    const Manifold2 m = manifoldObb2(a, b);
    bool manifold_ok = m.normal.allFinite() && m.count >= 0 && m.count <= 2;
    for (int i = 0; i < m.count; ++i) {
      manifold_ok = manifold_ok && m.points[static_cast<std::size_t>(i)].point.allFinite() &&
                    std::isfinite(m.points[static_cast<std::size_t>(i)].separation);
    }
    for (const Eigen::Vector2d& c : a.corners()) manifold_ok = manifold_ok && c.allFinite();
    if (!ok || !manifold_ok) {
      ++failures;
      ADD_FAILURE() << "case " << k << ": sep " << r.separation << " normal "
                    << r.normal.transpose() << " manifold " << m.count << "\nA " << text(a)
                    << "\nB " << text(b);
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
