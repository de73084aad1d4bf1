#pragma once
/// A loaded scene: the player's start, the parked cars, obstacles and walls. Plain data.

#include <Eigen/Core>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "geometry/aabb.hpp"
#include "geometry/convex_polygon.hpp"
#include "geometry/obb2.hpp"

namespace cardemo {

/// A parked car: a static box with an id.
struct ParkedCar {
  std::string id;            ///< Unique, non-empty.
  Obb2 box;                  ///< World box.
  double heading_deg = 0.0;  ///< Heading as written in the scene, degrees.
};

/// A static convex obstacle with an id.
struct Obstacle {
  std::string id;         ///< Unique among parked cars and obstacles.
  ConvexPolygon polygon;  ///< Convex, counter-clockwise.
};

/// The player's starting pose and body.
struct PlayerStart {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();          ///< Centre, world metres.
  double heading_deg = 0.0;                                    ///< Degrees CCW from +x.
  double length = 4.5;                                         ///< Metres along the heading.
  double width = 1.8;                                          ///< Metres across.
  int health = 100;                                            ///< Starting health (> 0).
  double speed = 0.0;                                          ///< Initial forward speed, m/s.
  double max_speed = std::numeric_limits<double>::infinity();  ///< Engine's speed cap, m/s.
};

/// Everything a scene file describes.
struct Scene {
  std::string name;                 ///< Display name.
  std::optional<Aabb2> bounds;      ///< Walls, when present.
  PlayerStart player;               ///< The player's car.
  std::vector<ParkedCar> parked;    ///< Static cars.
  std::vector<Obstacle> obstacles;  ///< Static convex polygons.
};

}  // namespace cardemo
