#pragma once
// Targets across the player's path and a drive into them, shared by the continuous-collision tests
// (tests/sim/world_ccd_test.cpp) and the lab's schemes (lab/tests/sim).

#include <sstream>
#include <string>
#include <variant>

#include "collision/narrow_phase.hpp"
#include "geometry/angle.hpp"
#include "scene_builders.hpp"
#include "sim/world.hpp"

namespace cardemo::test {

inline constexpr double kResting = 1e-4;  // restingPenetration near the origin

// A wall-like obstacle centred `distance` ahead of the player along `heading_deg`, its face turned
// by `face_deg` from square to the path: a 5 cm x 12 m kerb, or a parked car lying across.
struct Target {
  StaticShape shape;
  Eigen::Vector2d centre;
  Eigen::Vector2d normal;  // unit, facing the player's start
};

inline Target kerbAcross(double heading_deg, double face_deg, double distance) {
  const Eigen::Vector2d dir = unitFromDegrees(heading_deg);
  const Eigen::Vector2d centre = dir * distance;
  const Obb2 box = Obb2::fromDegrees(centre, heading_deg + face_deg, 0.05, 12.0);
  return {ConvexPolygon::fromObb(box), centre, -unitFromDegrees(heading_deg + face_deg)};
}

inline Target carAcross(double heading_deg, double face_deg, double distance) {
  const Eigen::Vector2d dir = unitFromDegrees(heading_deg);
  const Eigen::Vector2d centre = dir * distance;
  // Length across the path, so the 1.8 m width is what the player has to cross.
  const Obb2 box = Obb2::fromDegrees(centre, heading_deg + face_deg + 90.0, 4.5, 1.8);
  return {box, centre, -unitFromDegrees(heading_deg + face_deg)};
}

inline Scene sceneFor(const Target& t, double heading_deg, double speed) {
  Scene s = test::sceneWith({}, 0.0, 0.0, heading_deg);
  s.player.speed = speed;
  if (const Obb2* box = std::get_if<Obb2>(&t.shape)) {
    s.parked.push_back({"target", *box, 0.0});
  } else {
    s.obstacles.push_back({"target", std::get<ConvexPolygon>(t.shape)});
  }
  return s;
}

// Drives into the target with the collision scheme `mode` (null: the game's continuous one) and
// checks every frame: never deeper than the resting margin allows,
// the centre never on the far side; a hit on the target.
inline std::string driveInto(const Target& target, double heading_deg, double speed, double hz,
                             MotionScheme mode, const InputFrame& input, int frames,
                             const Eigen::Vector2d& offset = Eigen::Vector2d::Zero()) {
  WorldSettings settings;
  settings.hz = hz;
  settings.schemes.motion = mode;
  World world(test::translated(sceneFor(target, heading_deg, speed), offset), settings);
  std::ostringstream why;
  for (int f = 0; f < frames; ++f) {
    world.step(input);
    const double side = (world.car().position - offset - target.centre).dot(target.normal);
    const double sep = collidePlayer(world.carBox(), world.colliders().shape(0)).separation;
    if (side <= 0.0 || sep < -2.0 * kResting - 1e-9) {
      why << "frame " << world.frame() << ": centre " << side << " m in front of the target, sep "
          << sep;
      return why.str();
    }
  }
  if (world.hits().empty()) return "no hit";
  if (world.hits()[0].id != "target") return "hit the wrong thing";
  return "";
}

}  // namespace cardemo::test
