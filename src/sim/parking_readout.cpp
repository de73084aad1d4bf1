#include "sim/parking_readout.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace cardemo {
namespace {

// A position component smaller than this is not listed: it would read "0.0 m".
constexpr double kListedOffsetM = 0.05;

std::string metresText(double metres) {
  char text[32];
  // Below a decimetre (a tolerance tighter than 0.07 m) two decimals, so it never reads "0.0".
  std::snprintf(text, sizeof text, metres < 0.095 ? "%.2f m" : "%.1f m", metres);
  return text;
}

std::string tenthsText(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f s", seconds);
  return text;
}

}  // namespace

double nearBayDistance(const Goal& goal) {
  return std::max(goal.bay.length, goal.bay.width) + goal.position_tolerance;
}

std::vector<ParkingFix> parkingFixes(const Goal& goal, const ParkingCheck& check) {
  std::vector<ParkingFix> fixes;
  fixes.reserve(3);  // at most: along, across, turn
  if (check.distance > nearBayDistance(goal)) {
    fixes.push_back({ParkingFixKind::kToBay, check.distance});
    return fixes;
  }
  if (!check.position_ok) {
    const bool list_ahead = std::abs(check.ahead) >= kListedOffsetM;
    const bool list_left = std::abs(check.left) >= kListedOffsetM;
    // Both tiny happens only with a tolerance under 0.07 m: name the larger.
    const bool ahead_larger = std::abs(check.ahead) >= std::abs(check.left);
    if (list_ahead || (!list_left && ahead_larger)) {
      fixes.push_back({check.ahead >= 0.0 ? ParkingFixKind::kForward : ParkingFixKind::kBack,
                       std::abs(check.ahead)});
    }
    if (list_left || (!list_ahead && !ahead_larger)) {
      fixes.push_back({check.left >= 0.0 ? ParkingFixKind::kLeft : ParkingFixKind::kRight,
                       std::abs(check.left)});
    }
  }
  if (!check.heading_ok) {
    fixes.push_back({check.turn_deg >= 0.0 ? ParkingFixKind::kTurnLeft : ParkingFixKind::kTurnRight,
                     std::abs(check.turn_deg)});
  }
  // Stopping is the last thing: while the car still has to move, "stop" would contradict it.
  if (fixes.empty() && !check.speed_ok) fixes.push_back({ParkingFixKind::kStop, check.speed});
  return fixes;
}

std::vector<ParkingFix> parkingFixes(const Goal& goal, const Eigen::Vector2d& position,
                                     const Eigen::Vector2d& direction, double speed) {
  return parkingFixes(goal, checkParking(goal, position, direction, speed));
}

std::string fixText(const ParkingFix& fix) {
  const auto degrees = [](double d) {
    return std::to_string(std::max(1L, std::lround(d))) + "\xC2\xB0";
  };
  switch (fix.kind) {
    case ParkingFixKind::kForward:
      return metresText(fix.amount) + " forward";
    case ParkingFixKind::kBack:
      return metresText(fix.amount) + " back";
    case ParkingFixKind::kLeft:
      return metresText(fix.amount) + " left";
    case ParkingFixKind::kRight:
      return metresText(fix.amount) + " right";
    case ParkingFixKind::kTurnLeft:
      return "turn " + degrees(fix.amount) + " left";
    case ParkingFixKind::kTurnRight:
      return "turn " + degrees(fix.amount) + " right";
    case ParkingFixKind::kStop:
      return "stop";
    case ParkingFixKind::kToBay:
      return metresText(fix.amount) + " to the bay";
  }
  return {};
}

std::vector<std::string> fixTexts(const std::vector<ParkingFix>& fixes) {
  std::vector<std::string> out;
  out.reserve(fixes.size());
  for (const ParkingFix& f : fixes) out.push_back(fixText(f));
  return out;
}

std::string nextGateText(const GateCourse& gates) {
  const Gate* next = gates.nextGate();
  if (next == nullptr) return {};
  return "next gate " + std::to_string(gates.passed() + 1) + ": " + next->name;
}

std::string nextBayText(const ParkingChallenge& challenge) {
  if (challenge.bays().size() < 2 || challenge.parkedFrame()) return {};
  return "next bay " + std::to_string(challenge.currentBay() + 1) + "/" +
         std::to_string(challenge.bays().size());
}

std::string gateNoticeText(const GateCourse& gates, const GateNotice& notice) {
  const std::string number = std::to_string(notice.gate + 1);
  const std::string name =
      notice.gate < gates.size() ? std::string(gates.gates()[notice.gate].name) : std::string();
  switch (notice.kind) {
    case GateNotice::Kind::kPassed:
      return "gate " + number + " passed: " + name;
    case GateNotice::Kind::kMissed:
      return "missed gate " + number + ": " + name;
    case GateNotice::Kind::kWrongWay:
      return "gate " + number + " the wrong way: " + name;
  }
  return {};
}

std::vector<std::string> bayReadout(const ParkingChallenge& challenge) {
  if (challenge.over()) return {};
  const std::vector<ParkingFix> fixes = parkingFixes(challenge.goal(), challenge.lastCheck());
  if (!fixes.empty() && fixes.front().kind == ParkingFixKind::kToBay) return {};
  // The bay does not count yet: the gate, not the bay, is what to fix.
  if (!challenge.gates().done()) return {nextGateText(challenge.gates())};
  return fixTexts(fixes);
}

std::vector<std::string> notParkedReasons(const ParkingChallenge& challenge) {
  std::vector<std::string> reasons;
  if (challenge.parkedFrame()) return reasons;
  if (challenge.wrecked()) reasons.emplace_back("wrecked");
  if (challenge.timedOut()) reasons.emplace_back("time up");
  if (!challenge.gates().done()) reasons.push_back(nextGateText(challenge.gates()));
  if (std::string bay = nextBayText(challenge); !bay.empty()) reasons.push_back(std::move(bay));
  const std::vector<std::string> off =
      fixTexts(parkingFixes(challenge.goal(), challenge.lastCheck()));
  reasons.insert(reasons.end(), off.begin(), off.end());
  if (off.empty() && challenge.gates().done()) {
    char text[64];
    std::snprintf(text, sizeof text, "hold %.1f / %.1f s", challenge.heldSeconds(),
                  challenge.holdSeconds());
    reasons.emplace_back(text);
  }
  return reasons;
}

std::vector<StarReason> starReasons(const Goal& goal, const ParkingScore& score) {
  std::vector<StarReason> stars;
  stars.push_back({true, "parked"});
  stars.push_back(score.damage == 0 ? StarReason{true, "no damage"}
                                    : StarReason{false, std::to_string(score.damage) + " damage"});
  if (!goal.par_time) {
    stars.push_back({true, "no par time"});
  } else if (score.seconds <= *goal.par_time) {
    stars.push_back({true, "within par " + tenthsText(*goal.par_time)});
  } else {
    // At least 0.1: a run 0.04 s over par must not read "over par by 0.0 s".
    const double over = std::max(0.1, std::round((score.seconds - *goal.par_time) * 10.0) / 10.0);
    stars.push_back({false, "over par by " + tenthsText(over)});
  }
  return stars;
}

}  // namespace cardemo
