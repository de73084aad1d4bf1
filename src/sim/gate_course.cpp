#include "sim/gate_course.hpp"

#include <utility>

#include "geometry/exact_sign.hpp"
#include "geometry/segment_crossing.hpp"

namespace cardemo {

int gateSide(const Gate& gate, const Eigen::Vector2d& p) {
  return orientation(gate.from, gate.to, p);
}

GateCrossing crossGate(const Gate& gate, const Eigen::Vector2d& p0, const Eigen::Vector2d& p1,
                       int& last_side) {
  if (gate.kind == Gate::Kind::kBox) {
    if (!segmentMeetsQuad(p0, p1, gate.corners)) return GateCrossing::kNone;
    if (gate.direction && signOfAdvance(p0, p1, *gate.direction) <= 0) {
      return GateCrossing::kWrongWay;
    }
    return GateCrossing::kPassed;
  }
  const int side = gateSide(gate, p1);
  if (side == 0) return GateCrossing::kNone;  // on the line: decided when it leaves it
  const int before = last_side;
  last_side = side;
  if (before == 0 || before == side || !segmentsMeet(p0, p1, gate.from, gate.to)) {
    return GateCrossing::kNone;
  }
  if (gate.side != 0 && side != gate.side) return GateCrossing::kWrongWay;
  return GateCrossing::kPassed;
}

GateCourse::GateCourse(std::vector<Gate> gates)
    : gates_(std::move(gates)),
      sides_(gates_.size(), 0),
      crossings_(gates_.size(), GateCrossing::kNone) {
  passed_frames_.reserve(gates_.size());
}

void GateCourse::start(const Eigen::Vector2d& position) {
  for (std::size_t i = 0; i < gates_.size(); ++i) {
    sides_[i] = gates_[i].kind == Gate::Kind::kLine ? gateSide(gates_[i], position) : 0;
  }
}

void GateCourse::step(const Eigen::Vector2d& from, const Eigen::Vector2d& to, std::int64_t frame) {
  for (std::size_t i = 0; i < gates_.size(); ++i) {
    crossings_[i] = crossGate(gates_[i], from, to, sides_[i]);
  }
  // Several gates on one step (a fast car) are taken in their order.
  while (next_ < gates_.size() && crossings_[next_] == GateCrossing::kPassed) {
    passed_frames_.push_back(frame);
    last_notice_ = GateNotice{GateNotice::Kind::kPassed, next_, frame};
    ++next_;
  }
  if (next_ == gates_.size()) return;
  if (crossings_[next_] == GateCrossing::kWrongWay) {
    last_notice_ = GateNotice{GateNotice::Kind::kWrongWay, next_, frame};
  }
  for (std::size_t j = next_ + 1; j < gates_.size(); ++j) {
    if (crossings_[j] == GateCrossing::kPassed) {
      ++misses_;
      last_miss_ = GateNotice{GateNotice::Kind::kMissed, next_, frame};
      last_notice_ = last_miss_;
      break;
    }
  }
}

std::optional<std::int64_t> GateCourse::passedFrame(std::size_t i) const {
  if (i >= passed_frames_.size()) return std::nullopt;
  return passed_frames_[i];
}

}  // namespace cardemo
