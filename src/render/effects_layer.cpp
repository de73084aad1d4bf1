#include "render/effects_layer.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "render/hud.hpp"
#include "render/shapes.hpp"

namespace cardemo {
namespace {

constexpr double kSkidWidthM = 0.22;
constexpr int kSkidAlpha = 150;
// A damage number rises this far over its life, metres.
constexpr double kRiseM = 2.5;

Rgba withAlpha(Rgba c, double a) {
  c.a = static_cast<std::uint8_t>(std::clamp(std::lround(a), 0L, 255L));
  return c;
}

}  // namespace

void drawSkidMarks(Canvas& canvas, const Camera& camera, const Effects& effects,
                   const Palette& palette) {
  const Aabb2 view = visibleWorld(camera);
  const float w = std::max(1.0f, static_cast<float>(kSkidWidthM * camera.pixels_per_metre));
  const std::size_t n = effects.skidCount();
  const double cap =
      static_cast<double>(std::max<std::size_t>(1, effects.settings().max_skid_segments));
  auto draw = [&](const SkidSegment& s, double age_share) {
    const Aabb2 b{s.a.cwiseMin(s.b), s.a.cwiseMax(s.b)};
    if (!b.overlaps(view)) return;
    // Marks wear off as newer ones pile up: the oldest in a full buffer are at 40 %.
    const double a = kSkidAlpha * static_cast<double>(s.strength) * (1.0 - 0.6 * age_share);
    canvas.line(camera.toScreen(s.a), camera.toScreen(s.b), w, withAlpha(palette.skid, a));
  };
  for (std::size_t i = 0; i < n; ++i) draw(effects.skid(i), static_cast<double>(n - i) / cap);
  for (int i = 0; i < effects.openMarkCount(); ++i) {
    draw(effects.openMarks()[static_cast<std::size_t>(i)], 0.0);
  }
}

void drawDamageNumbers(Canvas& canvas, const Camera& camera, const Effects& effects,
                       const Palette& palette) {
  const float s = hudScale(camera.viewport);
  const int life = std::max(1, effects.settings().number_frames);
  for (const DamageNumber& n : effects.numbers()) {
    const double t = static_cast<double>(effects.frame() - n.frame) / life;
    if (t < 0.0 || t >= 1.0) continue;
    // Pops in large, settles, rises and fades over the last 40 % of its life.
    const double grow = 1.0 + 0.6 * std::max(0.0, 1.0 - t * 8.0);
    const int px = static_cast<int>(std::lround((22.0 + 0.35 * n.damage) * s * grow));
    const double alpha = 255.0 * std::min(1.0, (1.0 - t) / 0.4);
    // Appended, not "-" + string: GCC 12 at -O3 warns falsely (-Wrestrict) on the prepending form.
    std::string text(1, '-');
    text += std::to_string(n.damage);
    const Eigen::Vector2f size = canvas.textSize(text, px);
    const Eigen::Vector2f at = camera.toScreen(n.at + Eigen::Vector2d{0.0, kRiseM * t}) -
                               0.5f * size - Eigen::Vector2f{0.0f, 0.6f * size.y()};
    canvas.text(at + Eigen::Vector2f{2.0f, 2.0f}, text, px, withAlpha({0, 0, 0}, alpha * 0.8));
    canvas.text(at, text, px, withAlpha(palette.damage_text, alpha));
  }
}

void drawHealthPulse(Canvas& canvas, const World& world, const Effects& effects) {
  const float p = effects.healthPulse();
  if (p <= 0.0f) return;
  const HealthBarRect bar = healthBarRect(canvas.size());
  const int max_health = world.scene().player.health;
  if (max_health <= 0) return;
  const float per = bar.size.x() / static_cast<float>(max_health);
  const float from = per * static_cast<float>(std::clamp(world.health(), 0, max_health));
  const float to = per * static_cast<float>(std::clamp(effects.healthBeforeHit(), 0, max_health));
  if (to > from) {
    // The health just lost, flashing white then red as it drains.
    fillRect(canvas, bar.top_left + Eigen::Vector2f{from, 0.0f}, {to - from, bar.size.y()},
             withAlpha({255, static_cast<std::uint8_t>(90 + 165 * p), 80}, 230.0 * p));
    // Over the bar's text: write it again on top, or a yellow-white flash hides a yellow-white
    // number.
    drawHealthLabel(canvas, bar.top_left, bar.size, world.health(), max_health);
  }
  const float grow = 6.0f * p;
  const Eigen::Vector2f tl = bar.top_left - Eigen::Vector2f{grow, grow};
  const Eigen::Vector2f sz = bar.size + Eigen::Vector2f{2.0f * grow, 2.0f * grow};
  const std::array<Eigen::Vector2f, 4> frame{tl, tl + Eigen::Vector2f{sz.x(), 0.0f}, tl + sz,
                                             tl + Eigen::Vector2f{0.0f, sz.y()}};
  outline(canvas, frame, 2.0f + 2.0f * p, withAlpha({255, 70, 50}, 255.0 * p));
}

}  // namespace cardemo
