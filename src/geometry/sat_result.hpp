#pragma once
/// Result of a separating-axis query.

#include <Eigen/Core>

namespace cardemo {

/// Separating-axis verdict for a 2D pair (A, B).
struct SatResult2 {
  bool hit = false;         ///< True when the shapes touch or overlap (separation <= 0).
  double separation = 0.0;  ///< Largest gap over the candidate axes, metres; <= 0 means overlap.
  Eigen::Vector2d normal = Eigen::Vector2d::UnitX();  ///< Unit axis of that gap, from A towards B.
};

/// Separating-axis verdict for a 3D pair (A, B).
struct SatResult3 {
  bool hit = false;         ///< True when the boxes touch or overlap (separation <= 0).
  double separation = 0.0;  ///< Largest gap over the non-degenerate candidate axes, metres.
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();  ///< Unit axis of that gap, from A towards B.
  int axis_index = 0;  ///< 0-2 faces of A, 3-5 faces of B, 6-14 edge pairs (6 + 3*i + j).
};

}  // namespace cardemo
