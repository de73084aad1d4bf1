#include "lab/kernels/car_closed_form.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "geometry/angle.hpp"

namespace cardemo {

SpeedAndDistance underThrottle(double v0, double net, double drag, double t) {
  assert(v0 >= 0.0 && net > 0.0 && drag >= 0.0 && t >= 0.0);
  if (drag == 0.0) return {v0 + net * t, v0 * t + 0.5 * net * t * t};
  // v' = net - drag v^2 is a Riccati equation with constant coefficients. With the terminal speed
  // V = sqrt(net/drag), k = sqrt(net drag) and r = v0/V, separation of variables gives
  // v = V tanh(kt + atanh r) for r < 1 and V coth(kt + acoth r) for r > 1; by the addition
  // theorems both are v = V (tanh kt + r) / (1 + r tanh kt), and integrating once more,
  // x = ln(cosh kt + r sinh kt) / drag. It is the quadratic-drag fall of Taylor, "Classical
  // Mechanics", 2005, sec. 2.4 (v = v_ter tanh(g t / v_ter)) with g -> net and a start speed.
  const double terminal = std::sqrt(net / drag);
  const double k = std::sqrt(net * drag);
  const double r = v0 / terminal;
  const double x = k * t;
  const double tanh_x = std::tanh(x);
  const double speed = terminal * (tanh_x + r) / (1.0 + r * tanh_x);
  double log_growth = 0.0;  // ln(cosh x + r sinh x), without cancellation at small x
  if (x < 20.0) {
    const double sinh_half = std::sinh(0.5 * x);
    log_growth = std::log1p(2.0 * sinh_half * sinh_half + r * std::sinh(x));
  } else {
    // cosh x + r sinh x = e^x (1 + r) / 2 * (1 + (1 - r) / (1 + r) e^(-2x)); avoids overflow.
    log_growth =
        x + std::log(0.5 * (1.0 + r)) + std::log1p((1.0 - r) / (1.0 + r) * std::exp(-2.0 * x));
  }
  return {speed, log_growth / drag};
}

SpeedAndDistance coasting(double v0, double rolling, double drag, double t) {
  assert(v0 >= 0.0 && rolling >= 0.0 && drag >= 0.0 && t >= 0.0);
  if (v0 == 0.0) return {0.0, 0.0};
  if (drag == 0.0) {
    if (rolling == 0.0) return {v0, v0 * t};
    const double moving = std::min(t, v0 / rolling);
    return {t >= v0 / rolling ? 0.0 : v0 - rolling * moving,
            v0 * moving - 0.5 * rolling * moving * moving};
  }
  if (rolling == 0.0) {
    // v' = -drag v^2: v = v0 / (1 + drag v0 t), x = ln(1 + drag v0 t) / drag.
    return {v0 / (1.0 + drag * v0 * t), std::log1p(drag * v0 * t) / drag};
  }
  // v' = -(rolling + drag v^2): with W = sqrt(rolling/drag), k = sqrt(rolling drag) and q = v0/W,
  // separation gives atan(v/W) = atan(q) - kt, so v = W tan(atan q - kt) = W (q - tan kt) /
  // (1 + q tan kt) until the car stops at kt = atan q; integrating, x = ln(cos kt + q sin kt) /
  // drag (Taylor, sec. 2.4, the same separation with the force and drag in one direction, as for a
  // ball thrown upward).
  const double w = std::sqrt(rolling / drag);
  const double k = std::sqrt(rolling * drag);
  const double q = v0 / w;
  const double stop = std::atan(q);
  const double x = std::min(k * t, stop);
  const double sin_half = std::sin(0.5 * x);
  const double distance = std::log1p(q * std::sin(x) - 2.0 * sin_half * sin_half) / drag;
  if (k * t >= stop) return {0.0, distance};
  const double tan_x = std::tan(x);
  return {std::max(0.0, w * (q - tan_x) / (1.0 + q * tan_x)), distance};
}

CarState alongArc(const CarState& start, double curvature, double distance) {
  CarState end = start;
  const double turn = curvature * distance;
  end.heading = start.heading + turn;
  end.direction = unitFromRadians(end.heading);
  if (turn == 0.0) {
    end.position = start.position + unitFromRadians(start.heading) * distance;
    return end;
  }
  // On the circle of radius 1/k the position is p0 + (sin h1 - sin h0, cos h0 - cos h1) / k; by the
  // sum-to-product identities that is the chord 2 sin(turn/2) / k along the heading h0 + turn/2,
  // which keeps its accuracy for small turns.
  const double chord = 2.0 * std::sin(0.5 * turn) / curvature;
  end.position = start.position + unitFromRadians(start.heading + 0.5 * turn) * chord;
  return end;
}

}  // namespace cardemo
