#pragma once
/// The run summary (`replay --json`) as the contract defines it.

#include <nlohmann/json.hpp>

#include "sim/world.hpp"

namespace cardemo {

/// Builds the summary JSON of a world after a run: scene, hz, frames, health, hits, final, hash,
/// stats.
[[nodiscard]] nlohmann::json summaryJson(const World& world);

}  // namespace cardemo
