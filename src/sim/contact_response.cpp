#include "sim/contact_response.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cardemo {

double closingSpeed(const CarState& car, const Eigen::Vector2d& normal) {
  const Eigen::Vector2d v = car.velocity();
  const double vn = v.x() * normal.x() + v.y() * normal.y();
  return vn > 0.0 ? vn : 0.0;
}

namespace {

// World velocity (vx, vy) with its closing part along `normal` taken away; fast impacts bounce back
// `restitution` of it. The tangential part loses at most `contact_friction` times the normal change
// (Coulomb's law on impulses, as in Box2D's contact solver: Catto, "Iterative Dynamics with
// Temporal Coherence", GDC 2005), never more than all of it. A normal along a world axis changes
// the other component only by friction. Returns whether anything was taken away.
bool removeClosingPart(double& vx, double& vy, const Eigen::Vector2d& normal,
                       const CarParams& params) {
  const double vn = vx * normal.x() + vy * normal.y();
  if (!(vn > 0.0)) return false;
  // Slow impacts do not bounce (Box2D's b2_velocityThreshold idea): otherwise a car held against a
  // wall by its throttle would bounce off and come back in ever smaller hops, each a new hit.
  const double restitution = vn > params.bounce_threshold ? params.restitution : 0.0;
  const double k = (1.0 + restitution) * vn;
  const double tx = vx - vn * normal.x();
  const double ty = vy - vn * normal.y();
  const double tangential = std::sqrt(tx * tx + ty * ty);
  const double friction = params.contact_friction * k;
  // Share of the tangential velocity kept: 0 when friction stops the sliding outright.
  const double kept = tangential > friction ? (tangential - friction) / tangential : 0.0;
  vx = tx * kept - restitution * vn * normal.x();
  vy = ty * kept - restitution * vn * normal.y();
  return true;
}

// Back into the car's frame: forward speed along the heading and lateral slip across it. When the
// response cancels a component exactly, rounding leaves a few ulps of |v| with an arbitrary sign;
// the car model branches on the sign of the speed, so that residue is made an exact zero (otherwise
// a mirrored or rotated scene, whose residue has the other sign, would brake where the original
// accelerates).
void setVelocity(CarState& car, double vx, double vy, double size_before) {
  const double speed = vx * car.direction.x() + vy * car.direction.y();
  const double slip = vy * car.direction.x() - vx * car.direction.y();
  const double residue = 8.0 * std::numeric_limits<double>::epsilon() * size_before;
  car.speed = std::abs(speed) <= residue ? 0.0 : speed;
  car.slip = std::abs(slip) <= residue ? 0.0 : slip;
}

// A wall across one world axis: whether the car closed on it, and the friction (m/s) it takes off
// the other component.
struct WallHit {
  bool closing = false;
  double friction = 0.0;
};

// `along` is the velocity component on the wall's axis and `side` (+1 or -1) the direction of the
// wall from the car; the same arithmetic as removeClosingPart for that normal.
WallHit bounceOffWall(double& along, double side, const CarParams& params) {
  const double vn = along * side;
  if (!(vn > 0.0)) return {};
  const double restitution = vn > params.bounce_threshold ? params.restitution : 0.0;
  along = 0.0 - restitution * vn * side;
  return {true, params.contact_friction * ((1.0 + restitution) * vn)};
}

// The component along a wall less its friction, never past 0 (removeClosingPart's `kept`).
double slideAlong(double tangential, double friction) {
  const double size = std::abs(tangential);
  const double kept = size > friction ? (size - friction) / size : 0.0;
  return tangential * kept;
}

double sizeOf(const CarState& car) {
  return std::abs(car.speed) + std::abs(car.slip);
}

}  // namespace

void removeClosingVelocity(CarState& car, const Eigen::Vector2d& normal, const CarParams& params) {
  const Eigen::Vector2d v = car.velocity();
  double vx = v.x(), vy = v.y();
  if (removeClosingPart(vx, vy, normal, params)) setVelocity(car, vx, vy, sizeOf(car));
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

namespace {

// The wall of each axis the box touches (kWallCount: none), the west or south one first.
struct TouchedSides {
  std::size_t x = kWallCount;
  std::size_t y = kWallCount;
};

TouchedSides touchedSides(const std::array<double, kWallCount>& depth) {
  TouchedSides t;
  if (depth[0] >= 0.0) {
    t.x = 0;
  } else if (depth[1] >= 0.0) {
    t.x = 1;
  }
  if (depth[2] >= 0.0) {
    t.y = 2;
  } else if (depth[3] >= 0.0) {
    t.y = 3;
  }
  return t;
}

// Which way a wall lies from the car along its axis: -1 for west and south, +1 for east and north.
double sideOf(std::size_t wall) {
  return wall % 2 == 0 ? -1.0 : 1.0;
}

// How far to move the car along a wall's axis so that it reaches only the resting penetration
// into it (0 when it reaches no further than that plus the slack).
double pushFrom(std::size_t wall, double depth, double rest, double slack) {
  if (wall == kWallCount || !(depth - rest > slack)) return 0.0;
  return -sideOf(wall) * (depth - rest);
}

}  // namespace

WallResponse touchedWalls(const CarState& car, const CarParams& params, const Aabb2& walls) {
  const std::array<double, kWallCount> depth = wallDepths(carBox(car, params).aabb(), walls);
  const TouchedSides t = touchedSides(depth);
  WallResponse out;
  for (const std::size_t wall : {t.x, t.y}) {
    if (wall == kWallCount) continue;
    out.walls[wall] = {true, closingSpeed(car, wallNormal(kWallSides[wall])), depth[wall]};
  }
  return out;
}

WallResponse respondToWalls(CarState& car, const CarParams& params, const Aabb2& walls) {
  const TouchedSides t = touchedSides(wallDepths(carBox(car, params).aabb(), walls));
  WallResponse out;
  if (t.x == kWallCount && t.y == kWallCount) return out;
  // Each wall bounces its own component and its friction slows the other one, both worked out from
  // the velocity before the walls, so a corner gives the same answer whichever wall is "x" (a
  // quarter turn of the scene swaps them). One wall alone is exactly removeClosingPart.
  const Eigen::Vector2d v = car.velocity();
  double vx = v.x(), vy = v.y();
  WallHit x_wall, y_wall;
  if (t.x != kWallCount) {
    out.walls[t.x].closing = std::max(0.0, vx * sideOf(t.x));
    x_wall = bounceOffWall(vx, sideOf(t.x), params);
  }
  if (t.y != kWallCount) {
    out.walls[t.y].closing = std::max(0.0, vy * sideOf(t.y));
    y_wall = bounceOffWall(vy, sideOf(t.y), params);
  }
  if (x_wall.closing) vy = slideAlong(vy, x_wall.friction);
  if (y_wall.closing) vx = slideAlong(vx, y_wall.friction);
  if (x_wall.closing || y_wall.closing) setVelocity(car, vx, vy, sizeOf(car));
  // Pushed back to the resting penetration, as a collider's push-out leaves it: a car held against
  // a wall stays in contact from one frame to the next instead of flickering (one hit, not many).
  const std::array<double, kWallCount> depth = wallDepths(carBox(car, params).aabb(), walls);
  const double rest = restingPenetration(car.position);
  const double slack = pushOutSlack(car.position);
  const double dx = pushFrom(t.x, t.x == kWallCount ? 0.0 : depth[t.x], rest, slack);
  const double dy = pushFrom(t.y, t.y == kWallCount ? 0.0 : depth[t.y], rest, slack);
  if (dx != 0.0 || dy != 0.0) {
    car.position.x() += dx;
    car.position.y() += dy;
    out.moved = true;
  }
  const std::array<double, kWallCount> after = wallDepths(carBox(car, params).aabb(), walls);
  for (const std::size_t wall : {t.x, t.y}) {
    if (wall == kWallCount) continue;
    out.walls[wall].depth = after[wall];
    out.walls[wall].touching = after[wall] >= 0.0;
  }
  return out;
}

}  // namespace cardemo
