#include "geometry/sweep_obb2.hpp"

#include <cmath>

#include "geometry/sweep_intervals.hpp"

namespace cardemo {

SweepResult2 sweepObb2(const Obb2& a, const Eigen::Vector2d& displacement, const Obb2& b) {
  // The same relative pose, radii and centre distances as collideObb2, so that the gap at t = 0
  // is that function's separation exactly; the speeds are the world dot products with d, so a
  // displacement exactly along an axis gives exactly zero speed on the other one.
  const Eigen::Vector2d dc = b.center - a.center;  // subtract in double first (STYLE 8)
  const Eigen::Vector2d& u = a.axis;
  const double tx = u.x() * dc.x() + u.y() * dc.y();
  const double ty = u.x() * dc.y() - u.y() * dc.x();
  const double c = u.x() * b.axis.x() + u.y() * b.axis.y();
  const double s = u.x() * b.axis.y() - u.y() * b.axis.x();
  const double ac = std::abs(c), as = std::abs(s);
  const double tbx = c * tx + s * ty;
  const double tby = c * ty - s * tx;
  const double radius[4] = {
      a.half.x() + ac * b.half.x() + as * b.half.y(),
      a.half.y() + as * b.half.x() + ac * b.half.y(),
      b.half.x() + ac * a.half.x() + as * a.half.y(),
      b.half.y() + as * a.half.x() + ac * a.half.y(),
  };
  const double centre[4] = {tx, ty, tbx, tby};
  const Eigen::Vector2d axes[4] = {a.axis, a.perp(), b.axis, b.perp()};
  SweepIntervals intervals;
  for (int i = 0; i < 4; ++i) {
    const double v = axes[i].x() * displacement.x() + axes[i].y() * displacement.y();
    intervals.add(centre[i] - radius[i], centre[i] + radius[i], v, axes[i], 1.0);
  }
  return intervals.result();
}

}  // namespace cardemo
