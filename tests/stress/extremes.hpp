#pragma once
// Random boxes and polygons whose coordinates and sizes range over the whole finite double range,
// for the finite-output tests (tests/stress, lab/tests/stress).

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cfloat>
#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include "geometry/angle.hpp"
#include "geometry/convex_polygon.hpp"
#include "geometry/finite.hpp"
#include "geometry/obb2.hpp"
#include "geometry/obb3.hpp"

namespace cardemo::testing {

// Magnitudes that stress overflow (sums and products of huge values), underflow (squares of tiny
// values) and cancellation (huge coordinates, tiny sizes).
// The largest sizes and coordinates are 1e300 so that the sum of a box's centre and extents is
// representable (a box reaching beyond DBL_MAX has no finite corners).
inline constexpr std::array<double, 12> kMagnitudes{0.0, DBL_MIN, 1e-300, 1e-160, 1e-15, 1e-3,
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

}  // namespace cardemo::testing
