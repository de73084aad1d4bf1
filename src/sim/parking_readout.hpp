#pragma once
/// The parking rule in a driver's words: what still keeps the car from being parked ("0.4 m
/// forward", "turn 5° left", "stop"), why a run is not parked, and each star earned or missed.
/// Pure functions of a goal and a check, pose or challenge; the window's readout, the end panels
/// and `replay --json` all say the same words.

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "sim/parking_goal.hpp"
#include "sim/scene.hpp"

namespace cardemo {

/// What a driver still has to do for one of the parking checks, in the car's own terms.
enum class ParkingFixKind : std::uint8_t {
  kForward,    ///< Move forward `amount` m: the bay's centre is ahead of the car's.
  kBack,       ///< Move back `amount` m.
  kLeft,       ///< Move left `amount` m.
  kRight,      ///< Move right `amount` m.
  kTurnLeft,   ///< Turn the car's nose `amount` degrees to the left.
  kTurnRight,  ///< Turn the car's nose `amount` degrees to the right.
  kStop,       ///< Stop: the car moves at `amount` m/s, faster than the goal's max_speed.
  kToBay,      ///< Not near the bay yet: `amount` m from the car's centre to the bay's.
};

/// One thing still off, and by how much (metres, degrees or m/s, per the kind; never negative).
struct ParkingFix {
  ParkingFixKind kind = ParkingFixKind::kToBay;  ///< What to do.
  double amount = 0.0;                           ///< How much.
  /// Equal kind and amount.
  [[nodiscard]] bool operator==(const ParkingFix&) const = default;
};

/// The car is near the bay, and the readout shows, when its centre is within this distance of
/// the bay's: the bay's longer side plus the position tolerance, m.
[[nodiscard]] double nearBayDistance(const Goal& goal);

/// What still fails in `check` (made by checkParking against `goal`), in the order a driver fixes
/// it: along the car (forward or back) and across it (left or right), each listed from 0.05 m
/// when the position fails; the heading (turn left or right) when it fails; then, only once
/// position and heading hold, the speed (stop). Empty when every check passes. A car farther
/// than nearBayDistance() from the bay gets one kToBay instead.
[[nodiscard]] std::vector<ParkingFix> parkingFixes(const Goal& goal, const ParkingCheck& check);

/// parkingFixes for a car pose: centre, unit heading direction, signed speed.
[[nodiscard]] std::vector<ParkingFix> parkingFixes(const Goal& goal,
                                                   const Eigen::Vector2d& position,
                                                   const Eigen::Vector2d& direction, double speed);

/// The words of one fix: "0.4 m forward", "0.3 m back", "0.2 m left", "0.2 m right", "turn 5°
/// left", "turn 5° right", "stop", "12.3 m to the bay" (metres to 0.1, degrees whole and at
/// least 1).
[[nodiscard]] std::string fixText(const ParkingFix& fix);

/// The words of each fix, in order.
[[nodiscard]] std::vector<std::string> fixTexts(const std::vector<ParkingFix>& fixes);

/// "next gate 2: NAME" for the challenge's next gate, or empty when every gate is passed.
[[nodiscard]] std::string nextGateText(const GateCourse& gates);

/// "next bay 2/3" for a chain of bays (the goal has `next_bays`) not yet all parked: the current
/// bay and how many there are; empty for a goal of one bay.
[[nodiscard]] std::string nextBayText(const ParkingChallenge& challenge);

/// The words of a gate notice: "gate 1 passed: NAME", "missed gate 2: NAME" (the gate skipped),
/// "gate 2 the wrong way: NAME".
[[nodiscard]] std::string gateNoticeText(const GateCourse& gates, const GateNotice& notice);

/// The readout of the challenge's last frame: its fixes' words while the car is near the bay and
/// some check fails (or nextGateText() alone while a gate is still to pass), else nothing (far
/// away, holding, or the run is over).
[[nodiscard]] std::vector<std::string> bayReadout(const ParkingChallenge& challenge);

/// Why the challenge's car is not parked (yet), for `replay --json` and the end panels: "wrecked"
/// or "time up" when that ended the run, nextGateText() while a gate is still to pass,
/// nextBayText() in a chain of bays, then what
/// its last frame lacks: the fixes' words ("12.3 m to the bay" when far), or "hold 0.2 / 0.5 s"
/// while every check holds. Empty once parked.
[[nodiscard]] std::vector<std::string> notParkedReasons(const ParkingChallenge& challenge);

/// One star of a parked run, earned or missed, and why.
struct StarReason {
  bool earned = false;  ///< The star was earned.
  std::string text;     ///< "parked", "no damage" or "6 damage", "within par 12.0 s" or "over
                        ///< par by 3.2 s" (or "no par time", always earned).
};

/// The stars of `score` against `goal`, in order: parking, damage, par (kMaxStars of them).
[[nodiscard]] std::vector<StarReason> starReasons(const Goal& goal, const ParkingScore& score);

}  // namespace cardemo
