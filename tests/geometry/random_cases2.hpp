#pragma once
/// Seeded random 2D boxes and convex polygons for the property tests (std::mt19937_64, fixed
/// seeds).

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "../support/random_class.hpp"
#include "../support/random_draws.hpp"
#include "geometry/convex_polygon.hpp"
#include "geometry/obb2.hpp"
#include "geometry/sat_result.hpp"

namespace cardemo::testing {

/// Random source with the distributions the cases need.
class Random {
 public:
  /// Seeded generator; every test uses its own fixed seed.
  explicit Random(std::uint64_t seed) : rng_(seed) {}
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) { return cardemo::testing::uniform(rng_, lo, hi); }
  /// Log-uniform in [lo, hi).
  double logUniform(double lo, double hi) { return cardemo::testing::logUniform(rng_, lo, hi); }
  /// Uniform integer in [lo, hi].
  int integer(int lo, int hi) { return uniformInt(rng_, lo, hi); }
  /// +1 or -1.
  double sign() { return integer(0, 1) == 0 ? -1.0 : 1.0; }
  /// sign() times logUniform(lo, hi), drawn in that order.
  double signedLogUniform(double lo, double hi) {
    const double s = sign();
    return s * logUniform(lo, hi);
  }
  /// Uniform unit vector.
  Eigen::Vector2d direction() {
    const double t = uniform(-std::numbers::pi, std::numbers::pi);
    return {std::cos(t), std::sin(t)};
  }
  /// direction() times a distance uniform in [lo, hi), drawn in that order.
  Eigen::Vector2d offset(double lo, double hi) {
    const Eigen::Vector2d d = direction();
    return d * uniform(lo, hi);
  }
  /// Point at a log-uniform distance (1 m .. max_radius) from the origin (direction drawn first).
  Eigen::Vector2d farPoint(double max_radius) {
    const Eigen::Vector2d d = direction();
    return d * logUniform(1.0, max_radius);
  }
  /// Box with a random heading and sides log-uniform in [lo, hi].
  Obb2 box(const Eigen::Vector2d& center, double lo, double hi) {
    return {center, direction(), {0.5 * logUniform(lo, hi), 0.5 * logUniform(lo, hi)}};
  }
  /// Box with sides in [1 cm, 100 m] and aspect ratio up to 1e4.
  Obb2 extremeBox(const Eigen::Vector2d& center) {
    const double length = logUniform(0.01, 100.0);
    const double aspect = logUniform(1.0, std::min(1e4, length / 0.01));
    Eigen::Vector2d half{0.5 * length, 0.5 * length / aspect};
    if (integer(0, 1) == 1) std::swap(half.x(), half.y());
    return {center, direction(), half};
  }
  /// Convex polygon of 3..16 vertices on an ellipse (sorted random angles), rotated, around
  /// `center`, in either winding.
  ConvexPolygon polygon(const Eigen::Vector2d& center, double lo, double hi) {
    for (;;) {
      std::vector<Eigen::Vector2d> points =
          pointsOnEllipse(integer(3, ConvexPolygon::kMaxVertices), center, lo, hi);
      if (integer(0, 1) == 1) std::reverse(points.begin(), points.end());
      if (auto p = ConvexPolygon::fromPoints(points)) return *p;
    }
  }
  /// Convex quadrilateral on an ellipse (as polygon()), rotated, around `center`.
  ConvexPolygon quadrilateral(const Eigen::Vector2d& center, double lo, double hi) {
    for (;;) {
      if (auto p = ConvexPolygon::fromPoints(pointsOnEllipse(4, center, lo, hi))) return *p;
    }
  }
  /// `n` points at sorted random angles on an ellipse with diameters log-uniform in [lo, hi],
  /// rotated at random, around `center` (counter-clockwise).
  std::vector<Eigen::Vector2d> pointsOnEllipse(int n, const Eigen::Vector2d& center, double lo,
                                               double hi) {
    std::vector<double> angles(static_cast<std::size_t>(n));
    for (double& t : angles) t = uniform(0.0, 2.0 * std::numbers::pi);
    std::sort(angles.begin(), angles.end());
    const double rx = 0.5 * logUniform(lo, hi), ry = 0.5 * logUniform(lo, hi);
    const Eigen::Vector2d u = direction();
    std::vector<Eigen::Vector2d> points;
    for (double t : angles) {
      const Eigen::Vector2d e{rx * std::cos(t), ry * std::sin(t)};
      points.push_back(
          center + Eigen::Vector2d(u.x() * e.x() - u.y() * e.y(), u.y() * e.x() + u.x() * e.y()));
    }
    return points;
  }
  /// Underlying engine.
  std::mt19937_64& engine() { return rng_; }

 private:
  std::mt19937_64 rng_;
};

/// Half-width of a box's projection on a unit direction.
inline double supportRadius(const Obb2& b, const Eigen::Vector2d& d) {
  return b.half.x() * std::abs(b.axis.dot(d)) + b.half.y() * std::abs(b.perp().dot(d));
}

/// Largest projection of a polygon's vertices on a direction, relative to a point.
inline double supportOffset(const ConvexPolygon& p, const Eigen::Vector2d& d,
                            const Eigen::Vector2d& from) {
  double best = -INFINITY;
  for (int i = 0; i < p.count; ++i) best = std::max(best, (p.vertex(i) - from).dot(d));
  return best;
}

/// The polygon translated by `t`.
inline ConvexPolygon translated(ConvexPolygon p, const Eigen::Vector2d& t) {
  for (int i = 0; i < p.count; ++i) p.vertices[static_cast<std::size_t>(i)] += t;
  return p;
}

/// Signed gap (min of B minus max of A) of two point sets along an axis, relative to `ref`.
template <class PA, class PB>
double signedGap(const PA& a, const PB& b, const Eigen::Vector2d& axis,
                 const Eigen::Vector2d& ref) {
  double amax = -INFINITY, bmin = INFINITY;
  for (const Eigen::Vector2d& p : a) amax = std::max(amax, (p - ref).dot(axis));
  for (const Eigen::Vector2d& p : b) bmin = std::min(bmin, (p - ref).dot(axis));
  return bmin - amax;
}

/// Polygon vertices as a vector (for signedGap).
inline std::vector<Eigen::Vector2d> pointsOf(const ConvexPolygon& p) {
  return {p.vertices.begin(), p.vertices.begin() + p.count};
}

}  // namespace cardemo::testing

namespace cardemo::testing {

/// Runs one seeded 2D class (named after the running test): kCasesPerClass pairs from
/// `make(rng)`; `check(a, b, index, f, stats)` compares the fast code with the oracle on one pair
/// and returns the oracle's result, which is tallied.
template <class Make, class Check>
ClassStats runPairClass(std::uint64_t seed, const Make& make, const Check& check) {
  return runRandomClass<Random>(currentTestName(), seed, kCasesPerClass,
                                [&](Random& rng, int i, Failures& f, ClassStats& stats) {
                                  const auto [a, b] = make(rng);
                                  const auto ex = check(a, b, i, f, stats);
                                  stats.tally(ex.hit, ex.separation);
                                });
}

/// Checks one fast SAT result in one argument order against the exact separation and hit.
/// `points_a`/`points_b` are the shapes' vertices, used to verify that the normal realises sep.
template <class PA, class PB>
void checkAgainstExact(const SatResult2& r, bool exact_hit, double exact_sep, const PA& points_a,
                       const PB& points_b, const Eigen::Vector2d& ref, int index, Failures& f,
                       ClassStats& stats) {
  // The context is formatted only for a failure.
  const auto fail = [&](const std::string& what) {
    std::ostringstream ctx;
    ctx.precision(17);
    ctx << what << " (sep " << r.separation << ", exact " << exact_sep << ", hit " << r.hit
        << ", exact hit " << exact_hit << ")";
    f.fail(index, ctx.str());
  };
  if (std::abs(exact_sep) > kHitTolerance && r.hit != exact_hit) fail("hit differs");
  const double err = std::abs(r.separation - exact_sep);
  stats.max_error = std::max(stats.max_error, err);
  if (!(err <= kSepTolerance)) fail("sep error too large");
  if (r.hit != (r.separation <= 0.0)) fail("hit disagrees with own sep");
  if (!(std::abs(r.normal.norm() - 1.0) <= 1e-12)) fail("normal not unit");
  // The normal must be an axis whose A-to-B gap is the reported separation (sign included).
  const double g = signedGap(points_a, points_b, r.normal, ref);
  if (!(std::abs(g - r.separation) <= kSepTolerance))
    fail("gap along normal is " + std::to_string(g));
}

}  // namespace cardemo::testing
