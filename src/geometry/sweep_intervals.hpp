#pragma once
/// The interval arithmetic shared by the swept separating-axis tests (sweep_obb2, sweep_polygon).
///
/// Along one candidate axis n (any non-zero length), measured from A's centre at t = 0, B's static
/// projection is [lo, hi] and A's is [-ra + t v, ra + t v] with v = n . d. They overlap exactly
/// when p <= t v <= q with p = lo - ra and q = hi + ra, a closed interval of t because the gap is
/// linear in t. The shapes touch at time t iff every axis's interval holds t (the separating axis
/// theorem applied at each t), so the contact times are the intersection of the per-axis intervals,
/// and the first contact is the latest entry (Ericson, Real-Time Collision Detection, 5.5.8 for
/// boxes; Eberly, "Dynamic Collision Detection using Oriented Bounding Boxes", for the per-axis
/// intervals).

#include <Eigen/Core>
#include <limits>

#include "geometry/sweep_result.hpp"

namespace cardemo {

/// Intersects the per-axis contact intervals of a translational sweep, one axis at a time.
class SweepIntervals {
 public:
  /// Adds one axis: `p` = lo - ra and `q` = hi + ra (p <= q), `v` = axis . displacement, all in the
  /// axis's own (unnormalised) units; `world_axis` is the axis in world coordinates and `length`
  /// its length. Ties keep the earlier axis, as the static SAT does.
  void add(double p, double q, double v, const Eigen::Vector2d& world_axis, double length) {
    // Static gap at t = 0 (the larger of the forward and backward gaps), as collideObb2 computes
    // it.
    const double forward = p, backward = -q;
    const double gap = (forward >= backward ? forward : backward) / length;
    if (first_ || gap > start_gap_) {
      start_gap_ = gap;
      start_axis_ = world_axis / length;
      if (forward < backward) start_axis_ = -start_axis_;
    }
    first_ = false;
    if (v == 0.0) {
      // Motion parallel to this axis's faces: the gap never changes, so the axis either overlaps
      // for every t or for none. Exact: no division by a rounded speed.
      if (p > 0.0 || q < 0.0) empty_ = true;
      return;
    }
    // v > 0: A approaches B's low side (entry at p, normal +n); v < 0: the high side (normal -n).
    const double enter = v > 0.0 ? p / v : q / v;
    const double leave = v > 0.0 ? q / v : p / v;
    if (enter > enter_) {
      enter_ = enter;
      enter_axis_ = world_axis / length;
      if (v < 0.0) enter_axis_ = -enter_axis_;
    }
    if (leave < leave_) leave_ = leave;
  }

  /// The verdict over t in [0, 1]: touching counts as contact; contact at t = 0 gives toi = 0 and
  /// the static SAT normal (the axis of least penetration).
  [[nodiscard]] SweepResult2 result() const {
    SweepResult2 r;
    r.start_separation = start_gap_;
    if (empty_ || enter_ > leave_ || enter_ > 1.0 || leave_ < 0.0) return r;
    r.hit = true;
    if (enter_ > 0.0) {
      r.toi = enter_;
      r.normal = enter_axis_;
    } else {
      r.toi = 0.0;
      r.normal = start_axis_;
    }
    return r;
  }

 private:
  double enter_ = -std::numeric_limits<double>::infinity();
  double leave_ = std::numeric_limits<double>::infinity();
  Eigen::Vector2d enter_axis_ = Eigen::Vector2d::UnitX();
  bool empty_ = false;
  bool first_ = true;
  double start_gap_ = 0.0;
  Eigen::Vector2d start_axis_ = Eigen::Vector2d::UnitX();
};

}  // namespace cardemo
