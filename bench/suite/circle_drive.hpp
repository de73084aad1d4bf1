#pragma once
/// The circling drive of scripts/replay_speed.py: its scene and its inputs, built in C++.

#include <cstddef>
#include <string>

#include "sim/input_frame.hpp"
#include "sim/scene.hpp"

namespace cardemo::bench {

/// Scene JSON (cardemo-scene/1) with the same numbers as replay_speed.py's lot_scene(n): `n`
/// parked cars in the large lot's layout around a 20 m clearing, walls, the player in the clearing.
[[nodiscard]] std::string circleSceneJson(std::size_t n);

/// circleSceneJson(n) through the scene parser, as `cardemo replay` loads it.
[[nodiscard]] Scene circleScene(std::size_t n);

/// Keys of frame `frame` of the circling replay: `4 UL` then `8 L`, repeated.
[[nodiscard]] InputFrame circleInput(std::size_t frame);

}  // namespace cardemo::bench
