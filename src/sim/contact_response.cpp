#include "sim/contact_response.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cardemo {

double closingSpeed(const CarState& car, const Eigen::Vector2d& normal) {
  const double vx = car.speed * car.direction.x();
  const double vy = car.speed * car.direction.y();
  const double vn = vx * normal.x() + vy * normal.y();
  return vn > 0.0 ? vn : 0.0;
}

namespace {

// World velocity (vx, vy) with its closing part along `normal` taken away; fast impacts bounce back
// `restitution` of it. A normal along a world axis changes only that axis's component. Returns
// whether anything was taken away.
bool removeClosingPart(double& vx, double& vy, const Eigen::Vector2d& normal,
                       const CarParams& params) {
  const double vn = vx * normal.x() + vy * normal.y();
  if (!(vn > 0.0)) return false;
  // Slow impacts do not bounce (Box2D's b2_velocityThreshold idea): otherwise a car held against a
  // wall by its throttle would bounce off and come back in ever smaller hops, each a new hit.
  const double restitution = vn > params.bounce_threshold ? params.restitution : 0.0;
  const double k = (1.0 + restitution) * vn;
  vx -= k * normal.x();
  vy -= k * normal.y();
  return true;
}

// Back onto the heading (the bicycle model has no side slip). When the response cancels the motion
// along the heading exactly, the projection leaves a few ulps of |v| with an arbitrary sign; the
// car model branches on the sign of the speed, so that residue is made an exact zero (otherwise a
// mirrored or rotated scene, whose residue has the other sign, would brake where the original
// accelerates).
void setSpeedFromVelocity(CarState& car, double vx, double vy, double speed_before) {
  const double speed = vx * car.direction.x() + vy * car.direction.y();
  const double residue = 8.0 * std::numeric_limits<double>::epsilon() * std::abs(speed_before);
  car.speed = std::abs(speed) <= residue ? 0.0 : speed;
}

}  // namespace

void removeClosingVelocity(CarState& car, const Eigen::Vector2d& normal, const CarParams& params) {
  double vx = car.speed * car.direction.x();
  double vy = car.speed * car.direction.y();
  if (removeClosingPart(vx, vy, normal, params)) setSpeedFromVelocity(car, vx, vy, car.speed);
}

double restingPenetration(const Eigen::Vector2d& position) {
  // Push-out stops just short of separation rather than at it: a car pushed to exactly sep = 0
  // can land at +1 ulp after rounding, read as "not touching", and the next frame's contact would
  // then count as a new hit. 0.1 mm (Box2D allows 5 mm of slop) is far above double rounding
  // anywhere in the contract's 1e7 m range, so it is the same value everywhere and a translated
  // scene behaves the same; it is also above float resolution within ~1 km of the origin, so an
  // engine in float world coordinates (Box2D) sees a resting contact steadily instead of
  // flickering (measured: with 1e-7 m, Box2D reported 5 hits for 2 in the garage replay). Beyond
  // 1e7 m the margin grows with the coordinate's ulp.
  const double scale = std::abs(position.x()) + std::abs(position.y());
  return std::max(1e-4, 2e-15 * scale);
}

double pushOutSlack(const Eigen::Vector2d& position) {
  // A push computed from a pose that was itself just pushed is a few ulps of the coordinates;
  // repeating it would only chase rounding.
  const double scale = std::abs(position.x()) + std::abs(position.y());
  return std::max(1e-10, 8e-16 * scale);
}

bool keepInsideWalls(CarState& car, const CarParams& params, const Aabb2& walls) {
  const Aabb2 box = carBox(car, params).aabb();
  double dx = 0.0, dy = 0.0;
  // Both walls act on the same world velocity, each on its own component, and the result goes back
  // onto the heading once: so a corner gives the same answer whichever wall is "x" (a quarter turn
  // of the scene swaps them).
  double vx = car.speed * car.direction.x();
  double vy = car.speed * car.direction.y();
  bool slowed = false;
  if (box.min.x() < walls.min.x()) {
    dx = walls.min.x() - box.min.x();
    slowed = removeClosingPart(vx, vy, Eigen::Vector2d(-1.0, 0.0), params) || slowed;
  } else if (box.max.x() > walls.max.x()) {
    dx = walls.max.x() - box.max.x();
    slowed = removeClosingPart(vx, vy, Eigen::Vector2d(1.0, 0.0), params) || slowed;
  }
  if (box.min.y() < walls.min.y()) {
    dy = walls.min.y() - box.min.y();
    slowed = removeClosingPart(vx, vy, Eigen::Vector2d(0.0, -1.0), params) || slowed;
  } else if (box.max.y() > walls.max.y()) {
    dy = walls.max.y() - box.max.y();
    slowed = removeClosingPart(vx, vy, Eigen::Vector2d(0.0, 1.0), params) || slowed;
  }
  if (slowed) setSpeedFromVelocity(car, vx, vy, car.speed);
  if (dx == 0.0 && dy == 0.0) return false;
  car.position.x() += dx;
  car.position.y() += dy;
  return true;
}

}  // namespace cardemo
