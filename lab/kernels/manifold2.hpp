#pragma once
/// Contact manifold between two 2D boxes: reference face, incident edge clipping, hysteresis.

#include <Eigen/Core>
#include <array>

#include "geometry/obb2.hpp"

namespace cardemo {

/// One contact point of a manifold.
struct ContactPoint2 {
  Eigen::Vector2d point =
      Eigen::Vector2d::Zero();  ///< World position on B's surface (incident side), metres.
  double separation = 0.0;      ///< Signed distance along the manifold normal; < 0 is penetration.
  int feature = 0;  ///< Stable id of (reference face, incident vertex) for warm starting.
};

/// Up to two contact points sharing one normal.
struct Manifold2 {
  std::array<ContactPoint2, 2> points{};              ///< First `count` entries are valid.
  int count = 0;                                      ///< 0 (separated), 1 or 2.
  Eigen::Vector2d normal = Eigen::Vector2d::UnitX();  ///< Unit, from A towards B.
  int reference_face = -1;  ///< 0-3 face of A, 4-7 face of B (face k has outward normal k*90 deg
                            ///< from the local +x); -1 none.
};

/// Settings for manifold construction.
struct ManifoldSettings {
  /// Points farther apart than this (metres) are not contacts; 0 gives touching-or-overlapping
  /// only.
  double max_separation = 0.0;
  /// A face of B must beat A's best face by this relative margin to be chosen (Box2D's
  /// k_relativeTol idea), so the reference face does not flip-flop between nearly equal faces.
  double relative_tolerance = 0.98;
  /// Absolute margin (metres) added to the relative one.
  double absolute_tolerance = 0.001;
};

/// Builds the manifold: picks the reference face by SAT with hysteresis (`previous_reference_face`
/// wins ties within tolerance), clips the incident edge against the reference face's side planes
/// (Sutherland-Hodgman), and keeps points within `max_separation`.
[[nodiscard]] Manifold2 manifoldObb2(const Obb2& a, const Obb2& b,
                                     const ManifoldSettings& settings = {},
                                     int previous_reference_face = -1);

}  // namespace cardemo
