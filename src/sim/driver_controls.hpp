#pragma once
/// The driver's side of a step: what each held pedal does (a press that began against the car's
/// motion only brakes, then holds the car), how long the steering key has been held (the
/// keyboard steering ramp), and the gear these give. Simulation state: World keeps and hashes it.

#include <cstdint>

#include "sim/car.hpp"
#include "sim/input_frame.hpp"

namespace cardemo {

/// What a pedal's press in progress does, decided at the step it began.
enum class PedalPress : std::uint8_t {
  kReleased = 0,  ///< Not held at the last step.
  kDrives = 1,    ///< Began at a standstill or along the pedal's direction: it drives that way.
  kBrakes = 2,    ///< Began while the car moved against the pedal's direction: it brakes the car to
                  ///< a standstill and holds it there until released.
};

/// The gear the HUD shows.
enum class Gear : std::uint8_t {
  kNeutral,  ///< N: at a standstill, no pedal engaged to drive it.
  kDrive,    ///< D: moving forward, or at a standstill with the throttle driving it forward.
  kReverse,  ///< R: moving backward, or at a standstill with Down driving it backward.
};

/// The letter of a gear: 'D', 'R' or 'N'.
[[nodiscard]] char gearLetter(Gear gear);

/// The driver's state between steps (World::step advances it before it moves the car).
struct DriverControls {
  PedalPress up = PedalPress::kReleased;    ///< The throttle's press in progress.
  PedalPress down = PedalPress::kReleased;  ///< Down's press in progress.
  /// Steps the steering key has been held without a break, this one included: +n for Left, -n for
  /// Right, 0 when neither or both are held.
  std::int64_t steer_steps = 0;

  /// Bitwise equality.
  [[nodiscard]] bool operator==(const DriverControls&) const = default;
};

/// The controls for a step with `keys` held, the car moving at `speed` (m/s, signed) at its start:
/// a pedal press that begins now drives unless the car moves against it (Down while moving
/// forward, Up while moving backward), in which case it brakes; a held press keeps its kind; the
/// steering count grows while one steering key stays held.
[[nodiscard]] DriverControls advanceControls(const DriverControls& before, const InputFrame& keys,
                                             double speed);

/// The keys the car obeys under `controls` (advanced for `keys`): a braking press acts as both
/// pedals (brake towards a standstill, then hold it), so that it never drives the other way.
[[nodiscard]] InputFrame pedalCommand(const DriverControls& controls, const InputFrame& keys);

/// Seconds the steering key has been held at the step `controls` describe, at `hz` steps a second.
[[nodiscard]] double steerHeldSeconds(const DriverControls& controls, double hz);

/// The wheel's speed away from the centre after the steering key has been held `held` seconds:
/// steer_ramp_start + steer_ramp_accel * held, at most steer_rate (radians per second).
[[nodiscard]] double steerRampRate(const CarParams& params, double held);

/// The wheel angle after one step of `dt` seconds from `steer` towards `target` (radians): a move
/// towards the centre runs at `steer_rate` and stops at the centre when the target lies beyond it
/// (the next step goes on from there); a move away from the centre runs at the ramp's rate after
/// `held` seconds of steering.
[[nodiscard]] double steerStep(const CarParams& params, double steer, double target, double held,
                               double dt);

/// The gear at a car speed (m/s, signed) and the controls of the last step.
[[nodiscard]] Gear gearOf(double speed, const DriverControls& controls);

}  // namespace cardemo
