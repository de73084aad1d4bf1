#include "lab/sim/collision_schemes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "geometry/angle.hpp"

namespace cardemo {

double moveDiscrete(StepMotion& motion, const CarState& /*start*/, const CarState& next) {
  motion.detectAt(next);
  return 1.0;
}

double moveSubstepped(StepMotion& motion, const CarState& start, const CarState& next) {
  const double dt = motion.dt();
  const double limit = motion.halfMinExtent();
  const double travel = std::sqrt(next.speed * next.speed + next.slip * next.slip) * dt;
  std::int64_t n = 1;
  // Continuous safety: no sub-step moves the car by more than half its smaller extent, so it
  // cannot pass through anything (the 2^20 cap only guards against absurd inputs).
  if (travel > limit) n = static_cast<std::int64_t>(std::min(std::ceil(travel / limit), 1048576.0));
  const double dh = wrapRadians(next.heading - start.heading);
  for (std::int64_t i = 1; i <= n; ++i) {
    CarState pose = next;
    if (i < n) {
      const double f = static_cast<double>(i) / static_cast<double>(n);
      pose.position.x() = start.position.x() + (next.position.x() - start.position.x()) * f;
      pose.position.y() = start.position.y() + (next.position.y() - start.position.y()) * f;
      if (dh != 0.0) {
        pose.heading = wrapRadians(start.heading + dh * f);
        pose.direction = unitFromRadians(pose.heading);
      } else {
        pose.heading = start.heading;
        pose.direction = start.direction;
      }
    }
    if (motion.detectAt(pose)) {
      motion.countSubsteps(i - 1);
      return static_cast<double>(i) / static_cast<double>(n);
    }
  }
  motion.countSubsteps(n - 1);
  return 1.0;
}

Aabb2 rotationProofBox(const Obb2& box) {
  // hypot, not norm(): squaring a half extent beyond 1e154 would overflow.
  const double radius = std::hypot(box.half.x(), box.half.y());
  const Eigen::Vector2d r{radius, radius};
  return {box.center - r, box.center + r};
}

}  // namespace cardemo
