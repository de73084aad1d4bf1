#pragma once
/// What the game sounds like at each drawn frame, decided from the World alone: engine loop levels
/// by speed, tyre screech, impacts. The platform's audio only carries the levels out.

#include <array>
#include <cstddef>
#include <cstdint>

#include "sim/input_frame.hpp"
#include "sim/world.hpp"

namespace cardemo {

/// Number of engine loops, recorded at rising pitches (assets/sounds/engine-1..4.wav).
inline constexpr std::size_t kEngineLoops = 4;

/// Tuning of the sound decisions.
struct SoundSettings {
  double top_speed = 40.0;       ///< Speed (m/s) at which the highest engine loop plays alone.
  double idle_level = 0.35;      ///< Engine level at a standstill, off throttle.
  double throttle_level = 0.25;  ///< Added to the engine level while the throttle is held.
  double slide_accel = 6.0;      ///< Lateral acceleration (m/s^2) where the tyres start to squeal.
  double slide_full_accel = 12.0;    ///< Lateral acceleration of a full-volume screech.
  double brake_screech_speed = 8.0;  ///< Braking above this speed (m/s) screeches.
  double min_slide_level = 0.6;      ///< Screech level whenever World::sliding() is true.
  double full_screech_slip = 4.0;    ///< Lateral slip (m/s) of a full-volume screech.
  double full_impact_damage = 50.0;  ///< Damage of a full-volume impact.
  double min_impact_level = 0.2;     ///< The gentlest hit is still heard at this level.
};

/// One frame's levels, each in [0, 1].
struct SoundFrame {
  std::array<double, kEngineLoops> engine{};  ///< Gain of each engine loop (equal-power fade).
  double screech = 0.0;                       ///< Tyre screech loop level (0: silent).
  double impact = 0.0;                        ///< Level of an impact to start this frame (0: none).
};

/// Gains of the engine loops at `speed` (m/s, either sign): the speed picks a point between two
/// adjacent loops, cross-faded with equal power (cos/sin), so loudness holds through the fade.
[[nodiscard]] std::array<double, kEngineLoops> engineGains(double speed,
                                                           const SoundSettings& settings = {});

/// Screech level from the car's motion: the lateral acceleration of the bicycle model,
/// v^2 tan(steer) / wheelbase, above `slide_accel`, or braking (Down) while rolling forwards
/// faster than `brake_screech_speed`.
[[nodiscard]] double screechLevel(const CarState& car, const CarParams& params,
                                  const InputFrame& input, const SoundSettings& settings = {});

/// Follows one game: call update() once per drawn frame.
class SoundMix {
 public:
  /// Uses `settings` for every decision.
  explicit SoundMix(SoundSettings settings = {}) : settings_(settings) {}
  /// The levels for this frame. `input` is the last step's input; `holding` is true while the
  /// simulation holds (pause, help): then the loops are silent. A hit that arrived since the last
  /// call (or a new game: fewer hits than before) starts an impact whose level follows the
  /// largest new damage. The screech is the larger of screechLevel() and, while World::sliding(),
  /// the slip speed's level. Once the game is over the engine and screech stop.
  [[nodiscard]] SoundFrame update(const World& world, const InputFrame& input, bool holding);

 private:
  SoundSettings settings_;
  std::size_t hits_heard_ = 0;
  std::int64_t last_frame_ = 0;
};

}  // namespace cardemo
