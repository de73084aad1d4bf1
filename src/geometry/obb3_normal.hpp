#pragma once
/// Internal to obb3.cpp and lab/geometry/obb3_paths.cpp: the unit normal of collideObb3's winning
/// axis from the pair's pose, whoever computed the pose (obb3.cpp's own, or a vector kernel's
/// stored copy), so both give it bit for bit alike.

#include <Eigen/Core>
#include <cmath>
#include <cstdint>

#include "geometry/bit_cast.hpp"
#include "geometry/obb3.hpp"

namespace cardemo::obb3_detail {

/// -v if `negate`, else v, without a branch (the sign bits flipped; -v has the same bits): a pair's
/// random heading makes the sign unpredictable.
[[gnu::always_inline]] inline Eigen::Vector3d negatedIf(bool negate, const Eigen::Vector3d& v) {
  const std::uint64_t flip = static_cast<std::uint64_t>(negate) << 63;
  Eigen::Vector3d out;
  for (int k = 0; k < 3; ++k) {
    out[k] = bitCast<double>(bitCast<std::uint64_t>(v[k]) ^ flip);
  }
  return out;
}

/// v / |v| (v itself when zero) with |v|^2 summed left to right, as Eigen's normalized() does
/// with SSE2; without SIMD (the WebAssembly build) Eigen sums x + (y + z), which rounds
/// differently, so the sum is written out.
inline Eigen::Vector3d unitOrZero(const Eigen::Vector3d& v) {
  const double length2 = v.x() * v.x() + v.y() * v.y() + v.z() * v.z();
  return length2 > 0.0 ? Eigen::Vector3d(v / std::sqrt(length2)) : v;
}

/// The world-frame unit axis of fast edge axis 6 + 3i + j, pointing from A towards B. Pose: any
/// type with r(k, j) = a_k . b_j and tk(k) = a_k . d (obb3.cpp's Pose3, or a kernel's stored pose).
template <class Pose>
Eigen::Vector3d fastEdgeNormal(const Obb3& a, const Pose& p, int axis) {
  // The indices from tables and the sign by negatedIf: no branch on the axis or on the sign, which
  // a pair's random heading makes unpredictable.
  static constexpr unsigned char kJ[9] = {0, 1, 2, 0, 1, 2, 0, 1, 2};
  static constexpr unsigned char kI1[9] = {1, 1, 1, 2, 2, 2, 0, 0, 0};
  static constexpr unsigned char kI2[9] = {2, 2, 2, 0, 0, 0, 1, 1, 1};
  const unsigned e = static_cast<unsigned>(axis - 6), j = kJ[e], i1 = kI1[e], i2 = kI2[e];
  const Eigen::Vector3d n = a.rotation().col(i2) * p.r(i1, j) - a.rotation().col(i1) * p.r(i2, j);
  const double along = p.tk(i2) * p.r(i1, j) - p.tk(i1) * p.r(i2, j);
  return negatedIf(along < 0.0, unitOrZero(n));
}

/// The normal of the winning axis, pointing from A towards B: a fast edge axis, or a stored column
/// whose sign the pose's t (A's faces) or tb (B's faces, tbk(j) = b_j . d) gives.
template <class Pose>
Eigen::Vector3d winningNormal(const Obb3& a, const Obb3& b, const Pose& p, int axis) {
  if (axis >= 6) return fastEdgeNormal(a, p, axis);
  if (axis < 3) {
    const Eigen::Vector3d n = a.rotation().col(axis);
    return p.tk(axis) < 0.0 ? Eigen::Vector3d(-n) : n;
  }
  const Eigen::Vector3d n = b.rotation().col(axis - 3);
  return p.tbk(axis - 3) < 0.0 ? Eigen::Vector3d(-n) : n;
}

}  // namespace cardemo::obb3_detail
