#pragma once
/// The parking challenge: whether the car is parked in the goal bay, the level clock and the
/// score. Observes a World after each step and never changes it (the state hash does not include
/// it).

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "sim/gate_course.hpp"
#include "sim/scene.hpp"

namespace cardemo {

class World;

/// How far the car is from being parked at one instant.
struct ParkingCheck {
  double distance = 0.0;           ///< Between the car's centre and the bay's, m.
  double heading_error_deg = 0.0;  ///< Heading difference, degrees in [0, 180] (or [0, 90] when
                                   ///< either direction counts).
  bool position_ok = false;        ///< distance <= position_tolerance.
  bool heading_ok = false;         ///< heading_error_deg <= heading_tolerance_deg.
  bool speed_ok = false;           ///< |speed| <= max_speed.
  double ahead = 0.0;  ///< The bay's centre ahead of the car's along its heading, m (< 0: behind).
  double left = 0.0;   ///< The bay's centre to the car's left, m (< 0: to its right).
  double turn_deg = 0.0;  ///< Turn that brings the car's heading onto the nearest accepted one,
                          ///< degrees, > 0 to the left (counter-clockwise); |turn_deg| is
                          ///< heading_error_deg.
  double speed = 0.0;     ///< |speed|, m/s.

  /// All three hold: the car is parked.
  [[nodiscard]] bool parked() const { return position_ok && heading_ok && speed_ok; }
};

/// The most bays a goal may chain after its first (`goal.next_bays`).
inline constexpr std::size_t kMaxNextBays = 15;

/// The goal's bays in the order they are parked: `bay`, then each of `next_bays`.
[[nodiscard]] std::vector<ParkingBay> goalBays(const Goal& goal);

/// Checks a car pose (centre, unit heading direction, signed speed) against a goal's `bay`.
[[nodiscard]] ParkingCheck checkParking(const Goal& goal, const Eigen::Vector2d& position,
                                        const Eigen::Vector2d& direction, double speed);

/// The result of a run against a goal.
struct ParkingScore {
  std::int64_t frames = 0;  ///< Frames on the level clock when the car parked (from its start).
  double seconds = 0.0;     ///< frames / hz.
  int damage = 0;           ///< Health lost up to that frame.
  int stars = 0;            ///< 1 + (no damage) + (within par time, or no par time given).

  /// True when this score beats `other`: more stars, then less time, then less damage.
  [[nodiscard]] bool betterThan(const ParkingScore& other) const;
};

/// The most stars a run can earn.
inline constexpr int kMaxStars = 3;

/// Stars for a parked run: one for parking, one for no damage, one for parking within the par
/// time (always earned when the goal has none).
[[nodiscard]] int starsFor(const Goal& goal, double seconds, int damage);

/// Frames allowed by the time limit at `hz`: ceil(time_limit * hz), or nullopt without a limit.
[[nodiscard]] std::optional<std::int64_t> limitFrames(const Goal& goal, double hz);

/// Frames the parked checks must hold at `hz`: ceil(hold_time * hz) (0: parked at once).
[[nodiscard]] std::int64_t holdFrames(const Goal& goal, double hz);

/// A parking challenge run beside a World: call observe() on frame 0 and after every step.
///
/// The goal's gates must all be passed, in order, before the parked checks count (GateCourse).
///
/// A goal with `next_bays` is a chain: the car parks in each bay in turn (the checks and the hold
/// of one bay, against that bay), and is parked when it parks in the last. Each bay's hold starts
/// after the previous bay is parked; the gates come before the first bay; the clock, the time
/// limit and the score run over the whole chain.
///
/// The level clock starts when the car first moves: at the last frame the car stood at the
/// position of the first frame observed, so a player reading the task loses no time, and a car
/// driven from frame 0 has the clock started at frame 0. The time limit counts from there too.
class ParkingChallenge {
 public:
  /// A challenge for `goal`; `hz` converts frames to seconds, `start_health` measures damage.
  ParkingChallenge(const Goal& goal, double hz, int start_health);

  /// Looks at the world's current frame. Does nothing once the challenge is over. The car is
  /// parked in the current bay at the frame where the checks have held on every frame since
  /// holdFrames() earlier; parked in the last bay, the challenge is won.
  void observe(const World& world);

  /// Frame at which the car was parked in the last bay (the checks held for the hold time).
  [[nodiscard]] std::optional<std::int64_t> parkedFrame() const { return parked_frame_; }
  /// The score, once parked.
  [[nodiscard]] std::optional<ParkingScore> score() const { return score_; }
  /// The time limit passed before the car parked.
  [[nodiscard]] bool timedOut() const { return timed_out_; }
  /// Health reached 0 before the car parked.
  [[nodiscard]] bool wrecked() const { return wrecked_; }
  /// Parked, timed out or wrecked: the run is decided.
  [[nodiscard]] bool over() const { return parked_frame_ || timed_out_ || wrecked_; }
  /// The world frame last observed (stops changing once the challenge is over).
  [[nodiscard]] std::int64_t frame() const { return frame_; }
  /// The frame at which the level clock started, once the car has moved.
  [[nodiscard]] std::optional<std::int64_t> clockStart() const { return clock_start_; }
  /// Frames on the level clock: since clockStart(), 0 before; stopped when the challenge is over.
  [[nodiscard]] std::int64_t clockFrames() const;
  /// The level clock in seconds (the timer).
  [[nodiscard]] double seconds() const;
  /// First frame of the current unbroken run of passing checks (the hold), if one is under way.
  [[nodiscard]] std::optional<std::int64_t> holdStart() const { return hold_start_; }
  /// Seconds the checks have held so far (0 when they do not hold now).
  [[nodiscard]] double heldSeconds() const;
  /// The goal's hold time rounded up to whole frames, s (what heldSeconds() must reach).
  [[nodiscard]] double holdSeconds() const;
  /// The last check made (for the HUD), against the current bay.
  [[nodiscard]] const ParkingCheck& lastCheck() const { return last_; }
  /// The goal, with `bay` the current bay: the bay to park in now (the last one once parked).
  [[nodiscard]] const Goal& goal() const { return goal_; }
  /// Every bay of the goal in order (goalBays()).
  [[nodiscard]] std::span<const ParkingBay> bays() const { return bays_; }
  /// Bays parked so far; bays().size() once the challenge is won.
  [[nodiscard]] std::size_t baysParked() const { return bay_frames_.size(); }
  /// Index in bays() of the current bay (the last one once all are parked).
  [[nodiscard]] std::size_t currentBay() const;
  /// Frame at which bay `i` was parked, if it is.
  [[nodiscard]] std::optional<std::int64_t> bayParkedFrame(std::size_t i) const;
  /// Steps per second.
  [[nodiscard]] double hz() const { return hz_; }
  /// The goal's gates and which of them are passed.
  [[nodiscard]] const GateCourse& gates() const { return gates_; }

 private:
  Goal goal_;
  std::vector<ParkingBay> bays_;
  std::vector<std::int64_t> bay_frames_;  // per parked bay, in order
  double hz_;
  int start_health_;
  std::optional<std::int64_t> limit_frames_;
  std::int64_t hold_frames_;
  std::optional<std::int64_t> hold_start_;
  std::optional<Eigen::Vector2d> start_position_;
  Eigen::Vector2d last_position_ = Eigen::Vector2d::Zero();
  GateCourse gates_;
  std::optional<std::int64_t> clock_start_;
  std::int64_t frame_ = 0;
  ParkingCheck last_;
  std::optional<std::int64_t> parked_frame_;
  std::optional<ParkingScore> score_;
  bool timed_out_ = false;
  bool wrecked_ = false;
};

}  // namespace cardemo
