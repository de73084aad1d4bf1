#include "sim/parking_goal.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/angle.hpp"
#include "geometry/trig.hpp"
#include "sim/world.hpp"

namespace cardemo {

std::vector<ParkingBay> goalBays(const Goal& goal) {
  std::vector<ParkingBay> bays{goal.bay};
  bays.insert(bays.end(), goal.next_bays.begin(), goal.next_bays.end());
  return bays;
}

ParkingCheck checkParking(const Goal& goal, const Eigen::Vector2d& position,
                          const Eigen::Vector2d& direction, double speed) {
  ParkingCheck c;
  const Eigen::Vector2d offset = goal.bay.center - position;
  c.distance = offset.norm();
  c.ahead = offset.dot(direction);
  c.left = direction.x() * offset.y() - direction.y() * offset.x();
  const Eigen::Vector2d bay_dir = unitFromDegrees(goal.bay.heading_deg);
  const double cross = bay_dir.x() * direction.y() - bay_dir.y() * direction.x();
  const double dot = bay_dir.dot(direction);
  // Signed angle from the bay's heading to the car's, counter-clockwise positive.
  double off = degreesFromRadians(trig::atan2(cross, dot));
  // Facing the other way is as good, and nearer, past a quarter turn.
  if (goal.either_direction && std::abs(off) > 90.0) off = off > 0.0 ? off - 180.0 : off + 180.0;
  c.heading_error_deg = std::abs(off);
  c.turn_deg = -off;
  c.speed = std::abs(speed);
  c.position_ok = c.distance <= goal.position_tolerance;
  c.heading_ok = c.heading_error_deg <= goal.heading_tolerance_deg;
  c.speed_ok = c.speed <= goal.max_speed;
  return c;
}

bool ParkingScore::betterThan(const ParkingScore& other) const {
  if (stars != other.stars) return stars > other.stars;
  if (seconds != other.seconds) return seconds < other.seconds;
  return damage < other.damage;
}

int starsFor(const Goal& goal, double seconds, int damage) {
  const bool within_par = !goal.par_time || seconds <= *goal.par_time;
  return 1 + (damage == 0 ? 1 : 0) + (within_par ? 1 : 0);
}

std::optional<std::int64_t> limitFrames(const Goal& goal, double hz) {
  if (!goal.time_limit) return std::nullopt;
  return static_cast<std::int64_t>(std::ceil(*goal.time_limit * hz));
}

std::int64_t holdFrames(const Goal& goal, double hz) {
  return static_cast<std::int64_t>(std::ceil(goal.hold_time * hz));
}

ParkingChallenge::ParkingChallenge(const Goal& goal, double hz, int start_health)
    : goal_(goal),
      bays_(goalBays(goal)),
      hz_(hz),
      start_health_(start_health),
      limit_frames_(limitFrames(goal, hz)),
      hold_frames_(holdFrames(goal, hz)),
      gates_(goal.gates) {
  bay_frames_.reserve(bays_.size());
}

std::size_t ParkingChallenge::currentBay() const {
  return std::min(bay_frames_.size(), bays_.size() - 1);
}

std::optional<std::int64_t> ParkingChallenge::bayParkedFrame(std::size_t i) const {
  if (i >= bay_frames_.size()) return std::nullopt;
  return bay_frames_[i];
}

void ParkingChallenge::observe(const World& world) {
  if (over()) return;
  const CarState& car = world.car();
  if (!start_position_) {
    start_position_ = car.position;
    gates_.start(car.position);
  } else {
    if (!clock_start_ && car.position != *start_position_) {
      clock_start_ = frame_;  // the last frame observed at the start: the step from it moved it
    }
    gates_.step(last_position_, car.position, world.frame());
  }
  last_position_ = car.position;
  frame_ = world.frame();
  last_ = checkParking(goal_, car.position, car.direction, car.speed);
  if (world.gameOver()) {
    wrecked_ = true;
    return;
  }
  if (!last_.parked() || !gates_.done()) {
    hold_start_.reset();
  } else if (!hold_start_) {
    hold_start_ = frame_;
  }
  if (hold_start_ && frame_ - *hold_start_ >= hold_frames_) {
    bay_frames_.push_back(frame_);
    if (bay_frames_.size() < bays_.size()) {
      // A bay of a chain: the next one is the goal now, its hold still to come.
      goal_.bay = bays_[bay_frames_.size()];
      hold_start_.reset();
      last_ = checkParking(goal_, car.position, car.direction, car.speed);
    } else {
      parked_frame_ = frame_;
      ParkingScore s;
      s.frames = clockFrames();
      s.seconds = seconds();
      s.damage = start_health_ - world.health();
      s.stars = starsFor(goal_, s.seconds, s.damage);
      score_ = s;
      return;
    }
  }
  if (limit_frames_ && clockFrames() >= *limit_frames_) timed_out_ = true;
}

std::int64_t ParkingChallenge::clockFrames() const {
  return clock_start_ ? frame_ - *clock_start_ : 0;
}

double ParkingChallenge::seconds() const {
  return static_cast<double>(clockFrames()) / hz_;
}

double ParkingChallenge::heldSeconds() const {
  return hold_start_ ? static_cast<double>(frame_ - *hold_start_) / hz_ : 0.0;
}

double ParkingChallenge::holdSeconds() const {
  return static_cast<double>(hold_frames_) / hz_;
}

}  // namespace cardemo
