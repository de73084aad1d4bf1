#pragma once
// Small scene builders and scripted drives shared by the World tests.

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "sim/world.hpp"

namespace cardemo::test {

inline ParkedCar parkedCar(const std::string& id, double x, double y, double heading_deg,
                           double length = 4.5, double width = 1.8) {
  return {id, Obb2::fromDegrees({x, y}, heading_deg, length, width), heading_deg};
}

inline Scene sceneWith(std::vector<ParkedCar> parked, double x = 0.0, double y = 0.0,
                       double heading_deg = 0.0) {
  Scene s;
  s.name = "test";
  s.player.position = {x, y};
  s.player.heading_deg = heading_deg;
  s.parked = std::move(parked);
  return s;
}

// Rows of parked cars with gaps, the player in the aisle at the origin facing +x.
inline Scene parkingLot(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  std::uniform_int_distribution<int> skip(0, 3);
  Scene s = sceneWith({});
  s.bounds = Aabb2{{-60.0, -40.0}, {60.0, 40.0}};
  int n = 0;
  for (int row = -3; row <= 3; ++row) {
    if (row == 0) continue;
    for (int col = -10; col <= 10; ++col) {
      if (skip(rng) == 0) continue;
      // Drawn one statement at a time: the order in which a call's arguments are evaluated is
      // unspecified (GCC and Clang differ), and the lot must be the same whichever compiled it.
      const double x = col * 2.6 + jitter(rng);
      const double y = row * 9.0 + jitter(rng);
      const double heading = 90.0 + 10.0 * jitter(rng);
      s.parked.push_back(parkedCar("P" + std::to_string(n++), x, y, heading));
    }
  }
  return s;
}

// A deterministic pseudo-random drive: segments of 20-120 frames holding random keys. The pedals
// are let go for one frame half way through a segment, so that a long hold still brakes and then
// drives the other way (a pedal held through the stop would hold the car: docs/controls.md).
inline std::vector<InputFrame> scriptedDrive(std::uint64_t seed, int frames) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> len(20, 120);
  std::uniform_int_distribution<int> keys(0, 15);
  std::vector<InputFrame> out;
  while (static_cast<int>(out.size()) < frames) {
    InputFrame in = InputFrame::fromBits(static_cast<std::uint8_t>(keys(rng)));
    if (!in.down) in.up = true;  // mostly moving
    const int n = len(rng);
    for (int i = n; i > 0 && static_cast<int>(out.size()) < frames; --i) {
      InputFrame step = in;
      if (i == n / 2) step.up = step.down = false;
      out.push_back(step);
    }
  }
  return out;
}

inline Scene translated(Scene s, const Eigen::Vector2d& d) {
  s.player.position += d;
  for (ParkedCar& p : s.parked) p.box.center += d;
  for (Obstacle& o : s.obstacles) {
    for (int i = 0; i < o.polygon.count; ++i) o.polygon.vertices[static_cast<std::size_t>(i)] += d;
  }
  if (s.bounds) {
    s.bounds->min += d;
    s.bounds->max += d;
  }
  return s;
}

inline Obstacle wallObstacle(const std::string& id, double x0, double y0, double x1, double y1) {
  const std::vector<Eigen::Vector2d> pts{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  return {id, *ConvexPolygon::fromPoints(pts)};
}

}  // namespace cardemo::test
