#pragma once
/// Oriented box in 3D and its 15-axis separating-axis test.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "geometry/aabb.hpp"
#include "geometry/sat_result.hpp"

namespace cardemo {

/// Oriented box: { center + R * p : |p_i| <= half_i }. The rotation R is stored exactly as computed
/// from the quaternion (see fromQuaternion); the exact oracle uses these same double entries. R is
/// private so that the box can carry frameDefect(R), computed once whenever R is set: the pair
/// queries' error bound needs it on every call (docs/architecture.md, "The 3D filter").
class Obb3 {
 public:
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  ///< Centre, metres.
  Eigen::Vector3d half = Eigen::Vector3d::Ones();    ///< Half extents along the box axes, metres.

  /// Box from centre, quaternion (w, x, y, z; normalised here; must be non-zero and finite) and
  /// full sizes along the box's own x, y, z.
  [[nodiscard]] static Obb3 fromQuaternion(const Eigen::Vector3d& center,
                                           const Eigen::Quaterniond& q,
                                           const Eigen::Vector3d& size);
  /// Columns are the box axes, world frame.
  [[nodiscard]] const Eigen::Matrix3d& rotation() const { return rotation_; }
  /// Stores `m` as the rotation as it is (any matrix; the queries stay exact for a stored matrix
  /// off a rotation, only slower) and recomputes frameDefect().
  void setRotation(const Eigen::Matrix3d& m);
  /// cardemo::frameDefect(rotation()), kept up to date by every write of the rotation.
  [[nodiscard]] double frameDefect() const { return frame_defect_; }
  /// Tight axis-aligned bounds.
  [[nodiscard]] Aabb3 aabb() const;

 private:
  Eigen::Matrix3d rotation_ = Eigen::Matrix3d::Identity();
  double frame_defect_ = 0x1p-51;  // frameDefect of the identity: its 4-ulp rounding allowance
};

/// 15-axis SAT (3 faces of A, 3 of B, 9 edge-edge cross products). Face axes work in A's frame.
/// Near-parallel edges: each edge-edge axis a_i x b_j is formed from the stored columns with
/// error-free (fma-based) 2x2 determinants, so it keeps full relative precision down to 1e-15 rad
/// and is exactly zero only when the edges are exactly parallel; such an axis is skipped, which is
/// exact because a parallel edge pair adds no face to the Minkowski difference that the other axes
/// do not already cover. Never reports a false "separated". Most edge axes are decided first in
/// A's frame from A^T B (the batch kernels' filter): only an axis whose gap lies within that form's
/// error bound takes the error-free path, so the verdict is always the error-free one and a
/// reported separation is within 2^-40 of the pair's scale of it.
[[nodiscard]] SatResult3 collideObb3(const Obb3& a, const Obb3& b);

/// Boolean form of collideObb3.
[[nodiscard]] bool overlapObb3(const Obb3& a, const Obb3& b);

/// How far the columns m_k are from a right-handed orthonormal frame: the largest
/// |m_k . m_l - delta_kl| and component of |(m_k1 x m_k2) - m_k| (k1, k2 the next indices
/// cyclically), plus 4 ulps for the rounding of this very computation; infinite for NaN. About
/// 2e-15 for rotations from fromQuaternion. It bounds the error of the A-frame edge gaps
/// (docs/architecture.md, "The 3D filter"); Obb3 stores it for its own rotation.
[[nodiscard]] double frameDefect(const Eigen::Matrix3d& m);

}  // namespace cardemo
