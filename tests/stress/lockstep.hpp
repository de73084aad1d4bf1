#pragma once
/// Runs a scene and its rigid image in lockstep and reports the first frame where they differ.

#include <cstdint>
#include <string>
#include <vector>

#include "scene_transform.hpp"
#include "sim/world.hpp"

namespace cardemo::stress {

/// How far the image run may drift from the original, mapped back into the original's frame.
struct Tolerance {
  double position = 0.0;            ///< Metres, at frame 0.
  double position_per_frame = 0.0;  ///< Metres added per frame simulated (rounding accumulates).
  double angle = 0.0;               ///< Radians (heading, steering), at frame 0.
  double angle_per_frame = 0.0;     ///< Radians added per frame.
  double speed = 0.0;               ///< m/s (speed and the hits' impact speeds).
  /// Speed differences also grow the heading and position budgets by what they can explain:
  /// heading by |dv| * yaw_gain * dt, position by (|dv| + |v| * heading budget) * dt.
  double yaw_gain = 0.0;  ///< Heading rate error per m/s of speed error, 1/s per (m/s) per s.
  /// Steering error per m/s of speed error (the lock narrows with speed), rad per m/s.
  double lock_gain = 0.0;
};

/// Largest differences seen over a run (the figures the docs quote).
struct Deviation {
  double position = 0.0;  ///< Metres.
  double angle = 0.0;     ///< Radians.
  double speed = 0.0;     ///< m/s.
};

/// Outcome of one lockstep run.
struct LockstepResult {
  std::string divergence;         ///< Empty, or "frame F: FIELD: original A, image B (...)".
  Deviation worst;                ///< Largest differences while the runs agreed.
  std::int64_t frames = 0;        ///< Frames compared.
  std::size_t hits = 0;           ///< Hits of the original run.
  std::size_t hits_compared = 0;  ///< Hits that matched (up to the divergence).
  bool game_over = false;         ///< The original run ended in game over.
};

/// Steps World(original) with `inputs` and World(transformed(original, t)) with the mirrored
/// inputs; after every frame compares hits (frame, id, damage, impact speed), health, game over,
/// position (mapped back), heading, steering and speed. Stops at the first divergence.
[[nodiscard]] LockstepResult runLockstep(const Scene& original, const RigidTransform& t,
                                         const WorldSettings& settings,
                                         const std::vector<InputFrame>& inputs,
                                         const Tolerance& tolerance);

}  // namespace cardemo::stress
