#pragma once
/// A loaded scene: the player's start, the parked cars, obstacles and walls. Plain data.

#include <Eigen/Core>
#include <array>
#include <cstdint>
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

/// A parking bay: the rectangle the player must park in.
struct ParkingBay {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();  ///< Centre, world metres.
  double heading_deg = 0.0;  ///< Direction the parked car should face, degrees CCW from +x.
  double length = 5.5;       ///< Metres along the heading.
  double width = 2.6;        ///< Metres across.
};

/// A checkpoint of a goal (`goal.gates` in the scene file), passed when the car's centre crosses
/// its line, or enters its box, on one step (sim/gate_course states the exact rule).
struct Gate {
  /// A line to cross or a box to pass through.
  enum class Kind : std::uint8_t { kLine, kBox };
  Kind kind = Kind::kLine;                         ///< Line or box.
  std::string name;                                ///< Said in messages ("missed gate 2: NAME").
  Eigen::Vector2d from = Eigen::Vector2d::Zero();  ///< Line: one end, world metres.
  Eigen::Vector2d to = Eigen::Vector2d::Zero();    ///< Line: the other end.
  /// Box: corners, counter-clockwise, world metres (zero for a line: Eigen leaves its vectors
  /// uninitialised otherwise, and scenes are compared bit for bit).
  std::array<Eigen::Vector2d, 4> corners = {Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(),
                                            Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
  Eigen::Vector2d center = Eigen::Vector2d::Zero();  ///< Box centre, or the line's midpoint.
  /// Required direction of travel through the gate, a unit vector (nullopt: either way).
  std::optional<Eigen::Vector2d> direction;
  /// Line with a direction: the side of from -> to the crossing must end on (+1 left, -1 right).
  int side = 0;
};

/// The parking challenge of a scene (`goal` in the scene file).
struct Goal {
  ParkingBay bay;                      ///< Where to park.
  double position_tolerance = 0.5;     ///< Largest distance between car and bay centres, m.
  double heading_tolerance_deg = 8.0;  ///< Largest heading error, degrees.
  bool either_direction = false;       ///< Facing opposite to the bay heading also counts.
  double max_speed = 0.3;              ///< Largest |speed| that counts as stopped, m/s.
  double hold_time = 0.5;  ///< How long position, heading and speed must hold before PARKED, s.
  std::optional<double> par_time;    ///< Time for three stars, s.
  std::optional<double> time_limit;  ///< The run ends unparked after this long, s.
  std::vector<Gate> gates;           ///< Checkpoints to pass in order before the bay counts.
  /// More bays to park in, in order, after `bay` (a chain of bays; empty: `bay` alone).
  std::vector<ParkingBay> next_bays;
};

/// Marks a scene as a level of the scene picker (`level` in the scene file).
struct LevelInfo {
  int order = 1;      ///< Position in the picker, 1 first.
  std::string title;  ///< Shown in the picker.
  std::string task;   ///< What to do, one line for the player (empty: none given).
};

/// A painted mark on the ground: drawn, never collides (`markings` in the scene file).
struct Marking {
  /// What is painted.
  enum class Kind : std::uint8_t { kLine, kArrow };
  Kind kind = Kind::kLine;                         ///< Line or lane arrow.
  Eigen::Vector2d from = Eigen::Vector2d::Zero();  ///< Line start, or arrow tail.
  Eigen::Vector2d to = Eigen::Vector2d::Zero();    ///< Line end, or arrow tip.
  double width = 0.15;                             ///< Paint width, m.
};

/// Everything a scene file describes.
struct Scene {
  std::string name;                 ///< Display name.
  std::optional<Aabb2> bounds;      ///< Walls, when present.
  PlayerStart player;               ///< The player's car.
  std::vector<ParkedCar> parked;    ///< Static cars.
  std::vector<Obstacle> obstacles;  ///< Static convex polygons.
  std::optional<Goal> goal;         ///< The parking challenge, when the scene has one.
  std::optional<LevelInfo> level;   ///< Set when the scene is a level of the picker.
  std::vector<Marking> markings;    ///< Painted lines and arrows (render only).
};

}  // namespace cardemo
