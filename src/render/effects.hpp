#pragma once
/// Hit feedback and tyre marks: a render-side observer of the World, fed once per simulated step.
/// Its timers count frames, never wall time, so a replay drawn at frame N looks the same every
/// time; it only reads the World, so replays and state hashes are untouched.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "sim/world.hpp"

namespace cardemo {

/// Tuning of the feedback; durations in simulated frames.
struct EffectsSettings {
  int flash_frames = 24;                 ///< How long a hit car flashes.
  int shake_frames = 36;                 ///< How long the screen shakes after a hit.
  double shake_px_per_damage = 0.55;     ///< Shake amplitude per point of damage, pixels.
  double max_shake_px = 22.0;            ///< Cap of the shake amplitude, pixels.
  int number_frames = 110;               ///< How long a damage number floats.
  int pulse_frames = 48;                 ///< How long the health bar pulses.
  std::size_t max_skid_segments = 3000;  ///< Ring-buffer capacity of tyre marks.
  std::size_t max_dents = 512;           ///< Dents kept (oldest dropped first).
  double skid_segment_m = 0.35;          ///< A mark is laid every this many metres per tyre.
  double slide_lateral_accel = 6.0;      ///< Lateral acceleration (m/s^2) where tyres slide.
  double hard_brake_decel = 5.0;         ///< Deceleration (m/s^2) that marks the road.
  double brake_light_decel = 2.5;        ///< Deceleration (m/s^2) that lights the brake lamps.
  double brake_mark_speed = 5.0;         ///< Braking faster than this (m/s) marks all four tyres.
  double mark_min_speed = 1.5;           ///< Slower than this (m/s) leaves no mark.
};

/// One straight piece of tyre mark, world metres.
struct SkidSegment {
  Eigen::Vector2d a = Eigen::Vector2d::Zero();  ///< Start.
  Eigen::Vector2d b = Eigen::Vector2d::Zero();  ///< End.
  float strength = 1.0f;                        ///< 0..1: how dark it is laid.
};

/// A damage number rising from the point of impact.
struct DamageNumber {
  Eigen::Vector2d at = Eigen::Vector2d::Zero();  ///< Where it started, world metres.
  int damage = 0;                                ///< Points taken.
  std::int64_t frame = 0;                        ///< Frame of the hit.
};

/// Who wears a dent.
inline constexpr std::uint32_t kPlayerDent = 0xffffffffu;

/// A dent at the contact side of a car, in the car's own frame (x along the heading).
struct Dent {
  std::uint32_t owner = kPlayerDent;                ///< Collider index, or kPlayerDent.
  Eigen::Vector2d local = Eigen::Vector2d::Zero();  ///< Point on the body, local metres.
  double radius = 0.3;                              ///< Size, metres.
  std::uint32_t seed = 0;                           ///< Varies the dent's outline.
};

/// The observer. Construct (or reset) with the world at its current frame, then call observe()
/// after every World::step. Nothing here allocates after construction.
class Effects {
 public:
  /// Starts watching `world` as it is now (hits already in it count as new).
  explicit Effects(const World& world, const EffectsSettings& settings = {});

  /// Forgets everything and starts again from `world` (after a restart).
  void reset(const World& world);
  /// Takes in one simulated step: new hits, the car's motion, tyre marks.
  void observe(const World& world);
  /// Lets `frames` frames pass with the World no longer stepped (the run has ended), so the last
  /// hit's flash, shake, number and pulse fade as they do while driving.
  void idle(int frames);

  /// Frame of the last observed step.
  [[nodiscard]] std::int64_t frame() const { return frame_; }
  /// Flash of the player's car, 1 at the hit fading to 0.
  [[nodiscard]] float playerFlash() const { return fade(player_flash_, settings_.flash_frames); }
  /// Flash of collider `index` (parked cars first), 1 at the hit fading to 0.
  [[nodiscard]] float colliderFlash(std::uint32_t index) const;
  /// Screen offset of the shake, pixels (zero when calm).
  [[nodiscard]] Eigen::Vector2f shake() const;
  /// Health-bar pulse, 1 at the hit fading to 0.
  [[nodiscard]] float healthPulse() const { return fade(pulse_, settings_.pulse_frames); }
  /// Health before the last hit (the pulse shows the lost part).
  [[nodiscard]] int healthBeforeHit() const { return health_before_; }

  /// True while the car is braking (World::braking at the last step).
  [[nodiscard]] bool braking() const { return braking_; }
  /// True while the car rolls backwards (World::reversing).
  [[nodiscard]] bool reversing() const { return reversing_; }
  /// True while the tyres lay marks this frame.
  [[nodiscard]] bool marking() const { return marking_; }

  /// Tyre marks, oldest first (at most settings().max_skid_segments).
  [[nodiscard]] std::size_t skidCount() const { return skid_count_; }
  /// The i-th oldest tyre mark.
  [[nodiscard]] const SkidSegment& skid(std::size_t i) const;
  /// Marks being laid now, from the last laid point to each tyre (empty span when not marking).
  [[nodiscard]] const std::array<SkidSegment, 4>& openMarks() const { return open_; }
  /// How many of openMarks() are in use.
  [[nodiscard]] int openMarkCount() const { return open_count_; }

  /// Damage numbers still floating; `age` of each is frame() - n.frame.
  [[nodiscard]] const std::vector<DamageNumber>& numbers() const { return numbers_; }
  /// Every dent, oldest first.
  [[nodiscard]] const std::vector<Dent>& dents() const { return dents_; }
  /// Settings in force.
  [[nodiscard]] const EffectsSettings& settings() const { return settings_; }

 private:
  [[nodiscard]] float fade(std::int64_t start, int frames) const;
  void takeHit(const World& world, const HitEvent& hit);
  void trackMotion(const World& world);
  void pushSkid(const SkidSegment& s);

  EffectsSettings settings_;
  std::int64_t frame_ = 0;
  std::size_t seen_hits_ = 0;
  std::int64_t player_flash_ = -1'000'000;
  std::int64_t pulse_ = -1'000'000;
  std::int64_t shake_start_ = -1'000'000;
  double shake_px_ = 0.0;
  int health_before_ = 0;
  std::vector<std::int64_t> collider_flash_;  // frame of the last hit per collider
  std::vector<SkidSegment> skids_;            // ring buffer
  std::size_t skid_head_ = 0;                 // index of the oldest
  std::size_t skid_count_ = 0;
  std::array<Eigen::Vector2d, 4> anchor_{};  // last laid point per tyre
  std::array<bool, 4> laying_{};
  std::array<SkidSegment, 4> open_{};
  int open_count_ = 0;
  std::vector<DamageNumber> numbers_;
  std::vector<Dent> dents_;
  double last_speed_ = 0.0;
  bool braking_ = false;
  bool reversing_ = false;
  bool marking_ = false;
};

/// Where the four tyres of a car box sit, world metres: front-left, front-right, rear-left,
/// rear-right (the axles `wheelbase` apart, centred on the box).
[[nodiscard]] std::array<Eigen::Vector2d, 4> tyrePositions(const Obb2& box, double wheelbase);

}  // namespace cardemo
