#pragma once
/// The numeric domain of the geometry and the cheap checks its debug asserts use.
///
/// Every query returns finite numbers (no NaN, no infinity) for finite shapes that lie within
/// kMaxCoordinate of the origin: any finite centre, size, vertex and unit axis in that range,
/// mixed in one call, from the smallest normal double up. The bound keeps a shape's own corners
/// representable (a box reaching past DBL_MAX has none) with room for the differences and sums
/// the queries form. Parsed input is far inside it (scenes and pair rows stop at 1e9 m).

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/convex_polygon.hpp"
#include "geometry/obb2.hpp"
#include "geometry/obb3.hpp"
#include "geometry/sat_result.hpp"

namespace cardemo {

/// Largest coordinate (centre plus extent, or vertex) the geometry accepts, metres.
inline constexpr double kMaxCoordinate = 1e300;

/// True when the box is finite, within kMaxCoordinate and its axis is unit (to 1e-9).
[[nodiscard]] inline bool inDomain(const Obb2& b) {
  return b.center.cwiseAbs().maxCoeff() + b.half.x() + b.half.y() <= kMaxCoordinate &&
         b.half.minCoeff() >= 0.0 && std::abs(b.axis.squaredNorm() - 1.0) <= 1e-9;
}

/// True when every vertex is finite and within kMaxCoordinate.
[[nodiscard]] inline bool inDomain(PolygonView p) {
  double largest = 0.0;
  for (int i = 0; i < p.count; ++i) largest = std::max(largest, p.vertex(i).cwiseAbs().maxCoeff());
  return p.count >= 3 && p.count <= ConvexPolygon::kMaxVertices && largest <= kMaxCoordinate;
}

/// True when the box is finite and within kMaxCoordinate (its rotation comes from fromQuaternion).
/// The rotation is finite iff its frame defect, which the box stores, is.
[[nodiscard]] inline bool inDomain(const Obb3& b) {
  return b.center.cwiseAbs().maxCoeff() + b.half.sum() <= kMaxCoordinate &&
         b.half.minCoeff() >= 0.0 && b.frameDefect() < std::numeric_limits<double>::infinity();
}

/// True when the verdict carries finite numbers only.
[[nodiscard]] inline bool isFinite(const SatResult2& r) {
  return std::isfinite(r.separation) && r.normal.allFinite();
}

/// True when the verdict carries finite numbers only.
[[nodiscard]] inline bool isFinite(const SatResult3& r) {
  return std::isfinite(r.separation) && r.normal.allFinite();
}

}  // namespace cardemo
