#pragma once
/// The run summary (`replay --json`) as the contract defines it.

#include <nlohmann/json.hpp>

#include "sim/bay_chain.hpp"
#include "sim/parking_goal.hpp"
#include "sim/world.hpp"

namespace cardemo {

/// Builds the summary JSON of a world after a run: scene, hz, frames, health, hits, final, hash,
/// stats, and the parking challenge's `parked` (frame or null), `score` (null unless parked),
/// `clock_start` (the level clock's first frame, or null), `not_parked` (why not, or []),
/// `gates` (gatesJson) and `bays` (baysJson), both null without a goal.
[[nodiscard]] nlohmann::json summaryJson(const World& world,
                                         const ParkingChallenge* challenge = nullptr);

/// Free drive's bay chain as JSON: count (bays parked), bay (the highlighted bay's id, or null),
/// bays (how many the lot has), clock_frames and over.
[[nodiscard]] nlohmann::json bayChainJson(const BayChain& chain);

/// A goal's gates as JSON: total, passed (count), names (of the gates passed, in order), next
/// (the next gate's name, or null) and misses (steps that passed a later gate first).
[[nodiscard]] nlohmann::json gatesJson(const GateCourse& course);

/// A goal's bays as JSON: total (1, or more in a chain), parked (how many so far) and frames (the
/// frame each of those was parked at, in order).
[[nodiscard]] nlohmann::json baysJson(const ParkingChallenge& challenge);

/// The score as JSON: frames, seconds, damage, stars.
[[nodiscard]] nlohmann::json scoreJson(const ParkingScore& score);

}  // namespace cardemo
