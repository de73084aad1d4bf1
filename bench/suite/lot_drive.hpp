#pragma once
/// The whole-step benchmark's drive: a car that keeps close to a row of parked cars.

#include <cstddef>
#include <vector>

#include "geometry/obb2.hpp"
#include "sim/input_frame.hpp"
#include "sim/scene.hpp"

namespace cardemo::bench {

/// A drive of plain inputs, with what it does near the parked cars.
struct LotDrive {
  std::vector<InputFrame> inputs;  ///< One key set per step.
  double near_share = 0.0;         ///< Share of steps ending within 1 m of a parked car.
  double contact_share = 0.0;      ///< Share of steps ending in contact with one.
  std::size_t hits = 0;            ///< Hits (first contacts) over the drive.
};

/// `frames` steps at `hz` for lotScene: forward down the middle aisle and back in reverse,
/// holding the car 0.3-0.7 m from the bumpers of the north row and steering into them for 0.75 s
/// of every 4 s. A controller watching a World picks the keys once; the result is plain inputs.
[[nodiscard]] LotDrive lotDrive(const Scene& scene, std::size_t frames, double hz);

/// Euclidean distance between two boxes (0 when they touch or overlap).
[[nodiscard]] double boxDistance(const Obb2& a, const Obb2& b);

}  // namespace cardemo::bench
