#pragma once
/// Result of a swept (continuous) separating-axis query.

#include <Eigen/Core>

namespace cardemo {

/// First contact of a shape A translating by a displacement over t in [0, 1] with a static B.
struct SweepResult2 {
  bool hit = false;  ///< True when A touches or overlaps B at some t in [0, 1].
  double toi = 1.0;  ///< First time of contact in [0, 1] (fraction of the displacement) when hit.
  Eigen::Vector2d normal = Eigen::Vector2d::UnitX();  ///< Unit contact normal from A towards B.
  double start_separation = 0.0;  ///< SAT separation at t = 0, metres (<= 0: in contact at t = 0).
};

}  // namespace cardemo
