#pragma once
/// Oriented box in 3D and its 15-axis separating-axis test.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "geometry/aabb.hpp"
#include "geometry/sat_result.hpp"

namespace cardemo {

/// Oriented box: { center + R * p : |p_i| <= half_i }. `rotation` is stored exactly as computed
/// from the quaternion (see fromQuaternion); the exact oracle uses these same double entries.
struct Obb3 {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  ///< Centre, metres.
  Eigen::Matrix3d rotation =
      Eigen::Matrix3d::Identity();                 ///< Columns are the box axes, world frame.
  Eigen::Vector3d half = Eigen::Vector3d::Ones();  ///< Half extents along the box axes, metres.

  /// Box from centre, quaternion (w, x, y, z; normalised here; must be non-zero and finite) and
  /// full sizes along the box's own x, y, z.
  [[nodiscard]] static Obb3 fromQuaternion(const Eigen::Vector3d& center,
                                           const Eigen::Quaterniond& q,
                                           const Eigen::Vector3d& size);
  /// Tight axis-aligned bounds.
  [[nodiscard]] Aabb3 aabb() const;
};

/// 15-axis SAT (3 faces of A, 3 of B, 9 edge-edge cross products). Face axes work in A's frame.
/// Near-parallel edges: each edge-edge axis a_i x b_j is formed from the stored columns with
/// error-free (fma-based) 2x2 determinants, so it keeps full relative precision down to 1e-15 rad
/// and is exactly zero only when the edges are exactly parallel; such an axis is skipped, which is
/// exact because a parallel edge pair adds no face to the Minkowski difference that the other axes
/// do not already cover. Never reports a false "separated".
[[nodiscard]] SatResult3 collideObb3(const Obb3& a, const Obb3& b);

/// Boolean form of collideObb3.
[[nodiscard]] bool overlapObb3(const Obb3& a, const Obb3& b);

}  // namespace cardemo
