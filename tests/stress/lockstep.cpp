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
  if (ha.size() != hb.size()) {
    const std::size_t k = std::min(ha.size(), hb.size());
    return at + "hits: original " + (k < ha.size() ? hitText(ha[k]) : "none") + ", image " +
           (k < hb.size() ? hitText(hb[k]) : "none");
  }
  // A frame's hits are listed by collider index, and the image of a wall may sort before
  // another wall where the original sorted after it (two walls in a corner): compare the new
  // hits as a set, each original hit by its collider's image.
  std::vector<HitEvent> new_a(ha.begin() + static_cast<std::ptrdiff_t>(hits_compared), ha.end());
  std::vector<HitEvent> new_b(hb.begin() + static_cast<std::ptrdiff_t>(hits_compared), hb.end());
  for (HitEvent& h : new_a) h.id = t.colliderImage(h.id);
  const auto by_frame_and_id = [](const HitEvent& x, const HitEvent& y) {
    return std::tie(x.frame, x.id) < std::tie(y.frame, y.id);
  };
  std::sort(new_a.begin(), new_a.end(), by_frame_and_id);
  std::sort(new_b.begin(), new_b.end(), by_frame_and_id);
  for (std::size_t k = 0; k < new_a.size(); ++k) {
    const HitEvent& x = new_a[k];
    const HitEvent& y = new_b[k];
    if (x.frame != y.frame || x.id != y.id || x.damage != y.damage ||
        !(std::abs(x.speed - y.speed) <= tol.speed)) {
      return at + "hit " + std::to_string(hits_compared + k) + ": original (collider mapped) " +
             hitText(x) + ", image " + hitText(y);
    }
    worst.speed = std::max(worst.speed, std::abs(x.speed - y.speed));
  }
  hits_compared = ha.size();
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
