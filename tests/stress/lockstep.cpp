#include "lockstep.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "geometry/angle.hpp"

namespace cardemo::stress {
namespace {

std::string number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string pointText(const Eigen::Vector2d& p) {
  return "(" + number(p.x()) + ", " + number(p.y()) + ")";
}

std::string hitText(const HitEvent& h) {
  return "{frame " + std::to_string(h.frame) + ", " + h.id + ", damage " +
         std::to_string(h.damage) + ", speed " + number(h.speed) + "}";
}

// What the speed differences seen so far can explain in heading and position.
struct Budget {
  double angle = 0.0;
  double position = 0.0;
};

// Compares the current frame of the two worlds; returns an empty string or the first difference.
std::string compareFrame(const World& a, const World& b, const RigidTransform& t,
                         const Tolerance& tol, std::size_t& hits_compared, Deviation& worst,
                         Budget& budget) {
  const std::string at = "frame " + std::to_string(a.frame()) + ": ";
  const auto& ha = a.hits();
  const auto& hb = b.hits();
  for (; hits_compared < std::max(ha.size(), hb.size()); ++hits_compared) {
    const std::size_t k = hits_compared;
    if (k >= ha.size()) return at + "hits: original none, image " + hitText(hb[k]);
    if (k >= hb.size()) return at + "hits: original " + hitText(ha[k]) + ", image none";
    if (ha[k].frame != hb[k].frame || ha[k].id != hb[k].id || ha[k].damage != hb[k].damage ||
        !(std::abs(ha[k].speed - hb[k].speed) <= tol.speed)) {
      return at + "hit " + std::to_string(k) + ": original " + hitText(ha[k]) + ", image " +
             hitText(hb[k]);
    }
    worst.speed = std::max(worst.speed, std::abs(ha[k].speed - hb[k].speed));
  }
  if (a.health() != b.health()) {
    return at + "health: original " + std::to_string(a.health()) + ", image " +
           std::to_string(b.health());
  }
  const double frames = static_cast<double>(a.frame());
  const CarState& ca = a.car();
  const CarState& cb = b.car();
  const double dt = 1.0 / a.settings().hz;
  const double dv = std::abs(cb.speed - ca.speed);
  budget.angle += dv * tol.yaw_gain * dt;
  budget.position += (dv + std::abs(ca.speed) * budget.angle) * dt;
  const Eigen::Vector2d back = t.inversePoint(cb.position);
  const double dp = (back - ca.position).norm();
  const double position_tol = tol.position + tol.position_per_frame * frames + budget.position;
  if (!(dp <= position_tol)) {
    return at + "position: original " + pointText(ca.position) + ", image " +
           pointText(cb.position) + " mapped back to " + pointText(back) + " (" + number(dp) +
           " m apart, tolerance " + number(position_tol) + ")";
  }
  const double angle_tol = tol.angle + tol.angle_per_frame * frames + budget.angle;
  const double dh = std::abs(wrapRadians(cb.heading - t.headingRad(ca.heading)));
  if (!(dh <= angle_tol)) {
    return at + "heading: original " + number(ca.heading) + ", image " + number(cb.heading) + " (" +
           number(dh) + " rad off, tolerance " + number(angle_tol) + ")";
  }
  const double ds = std::abs(cb.steer - t.turnSign() * ca.steer);
  if (!(ds <= angle_tol + tol.lock_gain * dv)) {
    return at + "steer: original " + number(ca.steer) + ", image " + number(cb.steer);
  }
  if (!(dv <= tol.speed)) {
    return at + "speed: original " + number(ca.speed) + ", image " + number(cb.speed);
  }
  worst.position = std::max(worst.position, dp);
  worst.angle = std::max({worst.angle, dh, ds});
  worst.speed = std::max(worst.speed, dv);
  return {};
}

}  // namespace

LockstepResult runLockstep(const Scene& original, const RigidTransform& t,
                           const WorldSettings& settings, const std::vector<InputFrame>& inputs,
                           const Tolerance& tolerance) {
  World a(original, settings);
  World b(transformed(original, t), settings);
  LockstepResult result;
  std::size_t hits_compared = 0;
  Budget budget;
  result.divergence = compareFrame(a, b, t, tolerance, hits_compared, result.worst, budget);
  for (const InputFrame& in : inputs) {
    if (!result.divergence.empty()) break;
    a.step(in);
    b.step(t.input(in));
    ++result.frames;
    result.divergence = compareFrame(a, b, t, tolerance, hits_compared, result.worst, budget);
  }
  result.hits = a.hits().size();
  result.hits_compared = hits_compared;
  result.game_over = a.gameOver();
  return result;
}

}  // namespace cardemo::stress
