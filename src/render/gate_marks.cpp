#include "render/gate_marks.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "render/hud.hpp"
#include "render/shapes.hpp"
#include "sim/parking_readout.hpp"

namespace cardemo {
namespace {

constexpr Rgba kPassed{90, 230, 120, 255};
constexpr Rgba kNext{255, 214, 70, 255};
constexpr Rgba kLater{200, 204, 212, 150};
constexpr const char* kTick = "\xE2\x9C\x93";

float metresToPixels(const Camera& camera, double metres) {
  return (camera.toScreen({metres, 0.0}) - camera.toScreen({0.0, 0.0})).norm();
}

void drawGate(Canvas& canvas, const Camera& camera, const Gate& gate, const std::string& label,
              const Rgba& color, float thickness) {
  if (gate.kind == Gate::Kind::kLine) {
    const Eigen::Vector2f a = camera.toScreen(gate.from);
    const Eigen::Vector2f b = camera.toScreen(gate.to);
    canvas.line(a, b, thickness, color);
    // Posts at the ends, so that a gate reads as a gate and not as paint.
    const float post = 2.0f * thickness;
    for (const Eigen::Vector2f& p : {a, b}) {
      fillRect(canvas, p - Eigen::Vector2f{post, post}, {2.0f * post, 2.0f * post}, color);
    }
  } else {
    std::array<Eigen::Vector2f, 4> quad;
    for (std::size_t i = 0; i < quad.size(); ++i) quad[i] = camera.toScreen(gate.corners[i]);
    outline(canvas, quad, thickness, color);
  }
  if (gate.direction) {
    const Eigen::Vector2d tail = gate.center - 0.6 * *gate.direction;
    const Eigen::Vector2d tip = gate.center + 0.6 * *gate.direction;
    arrow(canvas, camera.toScreen(tail), camera.toScreen(tip), thickness, 3.0f * thickness, color);
  }
  const int size = std::max(10, static_cast<int>(std::lround(0.9 * metresToPixels(camera, 1.0))));
  const Eigen::Vector2f extent = canvas.textSize(label, size);
  const Eigen::Vector2f at = camera.toScreen(gate.center) + Eigen::Vector2f{thickness * 2.0f, 0.0f};
  canvas.text(at - Eigen::Vector2f{0.0f, extent.y()}, label, size, color);
}

}  // namespace

void drawGates(Canvas& canvas, const Camera& camera, const ParkingChallenge& challenge) {
  const GateCourse& course = challenge.gates();
  const float base = std::max(2.0f, 2.0f * hudScale(canvas.size()));
  // The later ones first, so that the next gate is drawn over any it crosses.
  for (std::size_t i = course.size(); i-- > 0;) {
    const Gate& gate = course.gates()[i];
    const std::string number = std::to_string(i + 1);
    if (i < course.passed()) {
      drawGate(canvas, camera, gate, number + kTick, kPassed, base);
    } else if (i == course.passed()) {
      drawGate(canvas, camera, gate, number, kNext, 1.8f * base);
    } else {
      drawGate(canvas, camera, gate, number, kLater, base);
    }
  }
}

std::optional<std::string> freshGateWarning(const ParkingChallenge& challenge) {
  if (challenge.over()) return std::nullopt;
  const std::optional<GateNotice>& notice = challenge.gates().lastNotice();
  if (!notice || notice->kind == GateNotice::Kind::kPassed) return std::nullopt;
  const double age = static_cast<double>(challenge.frame() - notice->frame) / challenge.hz();
  if (age >= kGateNoticeSeconds) return std::nullopt;
  return gateNoticeText(challenge.gates(), *notice);
}

}  // namespace cardemo
