#include "render/hud.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/end_panel.hpp"
#include "render/hud_colors.hpp"
#include "render/shapes.hpp"

namespace cardemo {
namespace {

using hud_colors::kDim;
using hud_colors::kPanel;
using hud_colors::kText;
constexpr Rgba kTrough{55, 58, 64};
constexpr Rgba kBannerText{255, 220, 90, 255};
constexpr Rgba kBannerBackdrop{12, 14, 18, 235};

std::string format(const char* fmt, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

int px(float size, float scale) {
  return static_cast<int>(std::lround(size * scale));
}

// A panel of `lines` rows of text; returns nothing, draws at `top_left`.
void textPanel(Canvas& canvas, const Eigen::Vector2f& top_left,
               const std::vector<std::pair<std::string, Rgba>>& lines, int height, float pad) {
  float w = 0.0f;
  for (const auto& [s, c] : lines) w = std::max(w, canvas.textSize(s, height).x());
  const float row = static_cast<float>(height) * 1.3f;
  fillRect(canvas, top_left,
           {w + 2.0f * pad, row * static_cast<float>(lines.size()) + 2.0f * pad - 0.3f * height},
           kPanel);
  Eigen::Vector2f at = top_left + Eigen::Vector2f{pad, pad};
  for (const auto& [s, c] : lines) {
    canvas.text(at, s, height, c);
    at.y() += row;
  }
}

}  // namespace

float tableWidth(Canvas& canvas, const std::vector<HudRow>& rows, int text_px) {
  float label = 0.0f;
  float value = 0.0f;
  for (const HudRow& r : rows) {
    label = std::max(label, canvas.textSize(r.label, text_px).x());
    value = std::max(value, canvas.textSize(r.value, text_px).x());
  }
  return label + 1.5f * static_cast<float>(text_px) + value;
}

float drawTable(Canvas& canvas, const Eigen::Vector2f& top_left, float width,
                const std::vector<HudRow>& rows, int text_px) {
  const float row = static_cast<float>(text_px) * 1.3f;
  float y = top_left.y();
  for (const HudRow& r : rows) {
    canvas.text({top_left.x(), y}, r.label, text_px, r.color);
    if (!r.value.empty()) {
      const float w = canvas.textSize(r.value, text_px).x();
      canvas.text({top_left.x() + width - w, y}, r.value, text_px, r.color);
    }
    y += row;
  }
  return row * static_cast<float>(rows.size());
}

Rgba healthColor(double fraction) {
  const double f = std::clamp(fraction, 0.0, 1.0);
  auto lerp = [](double a, double b, double t) {
    return static_cast<std::uint8_t>(std::lround(a + (b - a) * t));
  };
  // Red (0) -> yellow (0.5) -> green (1), like the seed demo's bar.
  if (f < 0.5) return {lerp(220, 230, 2 * f), lerp(40, 200, 2 * f), 40, 255};
  return {lerp(230, 60, 2 * f - 1), lerp(200, 200, 2 * f - 1), lerp(40, 70, 2 * f - 1), 255};
}

float hudScale(const Eigen::Vector2i& viewport) {
  return std::clamp(static_cast<float>(viewport.y()) / 720.0f, 0.75f, 2.5f);
}

void drawHealthBar(Canvas& canvas, const Eigen::Vector2f& top_left, const Eigen::Vector2f& size,
                   int health, int max_health) {
  const double fraction =
      max_health > 0 ? std::clamp(static_cast<double>(health) / max_health, 0.0, 1.0) : 0.0;
  fillRect(canvas, top_left, size, kTrough);
  if (fraction > 0.0) {
    fillRect(canvas, top_left, {static_cast<float>(size.x() * fraction), size.y()},
             healthColor(fraction));
  }
  drawHealthLabel(canvas, top_left, size, health, max_health);
}

void drawHealthLabel(Canvas& canvas, const Eigen::Vector2f& top_left, const Eigen::Vector2f& size,
                     int health, int max_health) {
  const int h = std::max(8, static_cast<int>(size.y() * 0.72f));
  const std::string label = std::to_string(health) + " / " + std::to_string(max_health);
  const Eigen::Vector2f ts = canvas.textSize(label, h);
  const Eigen::Vector2f at = top_left + Eigen::Vector2f{6.0f, 0.5f * (size.y() - ts.y())};
  canvas.text(at + Eigen::Vector2f{1.0f, 1.0f}, label, h, {0, 0, 0, 200});
  canvas.text(at, label, h, kText);
}

HealthBarRect healthBarRect(const Eigen::Vector2i& viewport) {
  const float s = hudScale(viewport);
  const float pad = 10.0f * s;
  return {{12.0f * s + pad, 12.0f * s + pad}, {240.0f * s, 22.0f * s}};
}

namespace {

// Rows of the player's HUD table: speed and crashes (the developer rows come below them).
constexpr int kPlayerRows = 2;

// Height of the HUD panel holding the health bar and `rows` table rows, pixels.
float hudPanelHeight(const Eigen::Vector2i& viewport, std::size_t rows) {
  const float s = hudScale(viewport);
  const float row = static_cast<float>(px(16, s)) * 1.3f;
  return healthBarRect(viewport).size.y() + 10.0f * s * 2.5f + row * static_cast<float>(rows);
}

}  // namespace

ViewInsets hudInsets(const Eigen::Vector2i& viewport) {
  const float s = hudScale(viewport);
  const float panel_top = healthBarRect(viewport).top_left.y() - 10.0f * s;
  return {panel_top + hudPanelHeight(viewport, kPlayerRows) + 8.0f * s,
          static_cast<float>(viewport.y()) - statusLineTop(viewport)};
}

float statusLineTop(const Eigen::Vector2i& viewport) {
  const float s = hudScale(viewport);
  return static_cast<float>(viewport.y()) - 12.0f * s - 1.3f * static_cast<float>(px(14, s)) -
         10.0f * s;
}

Eigen::Vector2f drawHud(Canvas& canvas, const World& world, const DrawOptions& options) {
  const Eigen::Vector2i vp = canvas.size();
  const float s = hudScale(vp);
  const float pad = 10.0f * s;
  const int h = px(16, s);
  std::vector<HudRow> rows;
  rows.push_back({"Speed",
                  options.run_over ? std::string("stopped")
                                   : format("%.0f km/h", std::abs(world.car().speed) * 3.6),
                  kText});
  rows.push_back({"Crashes", std::to_string(world.damagingCrashes()), kText});
  // Developer rows: a player driving sees speed and crashes; the debug overlay (B), a replay's
  // playback and `cardemo render` add the frame, the overlay the raw hits (every first touch, as
  // the summary JSON counts them) and the frame rate.
  if (options.frame_counter || options.debug_overlay || options.playback_speed > 0.0) {
    rows.push_back({"Frame", std::to_string(world.frame()), kDim});
  }
  if (options.debug_overlay) rows.push_back({"Hits", std::to_string(world.hits().size()), kDim});
  if (options.debug_overlay && options.fps > 0.0) {
    rows.push_back({"FPS", format("%.0f", options.fps), kDim});
  }
  if (options.playback_speed > 0.0) {
    rows.push_back({"Replay speed", format("%gx", options.playback_speed), kDim});
  }
  const HealthBarRect bar = healthBarRect(vp);
  const Eigen::Vector2f bar_size = bar.size;
  const Eigen::Vector2f origin = bar.top_left - Eigen::Vector2f{pad, pad};
  // One panel behind both the bar and the table.
  const Eigen::Vector2f panel{bar_size.x() + 2.0f * pad, hudPanelHeight(vp, rows.size())};
  fillRect(canvas, origin, panel, kPanel);
  drawHealthBar(canvas, bar.top_left, bar_size, world.health(), world.scene().player.health);
  drawTable(canvas, origin + Eigen::Vector2f{pad, pad * 1.8f + bar_size.y()}, bar_size.x(), rows,
            h);

  const int small = px(14, s);
  if (!options.status.empty()) {
    textPanel(canvas, {12.0f * s, statusLineTop(vp)}, {{options.status, kDim}}, small, pad * 0.6f);
  }
  if (!options.help) {
    const std::string hint = "F1 help";
    const Eigen::Vector2f ts = canvas.textSize(hint, small);
    canvas.text({static_cast<float>(vp.x()) - ts.x() - 14.0f * s,
                 static_cast<float>(vp.y()) - ts.y() - 12.0f * s},
                hint, small, kDim);
  }
  return origin + panel;
}

void drawBanner(Canvas& canvas, const std::string& text) {
  if (text.empty()) return;
  const Eigen::Vector2i vp = canvas.size();
  const float s = hudScale(vp);
  const float pad = 14.0f * s;
  const int big = px(34, s);
  const Eigen::Vector2f ts = canvas.textSize(text, big);
  const Eigen::Vector2f box{ts.x() + 2.0f * pad, ts.y() + 2.0f * pad};
  // A third of the way down: clear of the timer and the HUD panels at the top, and above the
  // car, which the camera keeps near the centre.
  const Eigen::Vector2f tl{0.5f * (static_cast<float>(vp.x()) - box.x()),
                           static_cast<float>(vp.y()) / 3.0f - 0.5f * box.y()};
  fillRect(canvas, tl, box, kBannerBackdrop);
  canvas.text(tl + Eigen::Vector2f{pad, pad}, text, big, kBannerText);
}

void drawGameOver(Canvas& canvas, const World& world, const Camera& camera, const Obb2& player_box,
                  const std::vector<std::pair<std::string, std::string>>& summary_rows,
                  const std::string& keys) {
  EndPanel panel{"GAME OVER",
                 {255, 90, 80, 255},
                 {60, 10, 12, 215},
                 summary_rows,
                 keys.empty() ? std::string("Enter restart    Esc quit") : keys};
  if (panel.rows.empty()) {
    panel.rows = {
        {"Time", format("%.1f s", static_cast<double>(world.frame()) / world.settings().hz)},
        {"Crashes", std::to_string(world.damagingCrashes())},
        {"Damage", std::to_string(world.scene().player.health - world.health())}};
  }
  drawEndPanel(canvas, camera, player_box, panel);
}

const std::vector<std::pair<std::string, std::string>>& helpKeys() {
  static const std::vector<std::pair<std::string, std::string>> keys{
      {"Up / Down, W / S", "throttle / brake, then reverse"},
      {"Left / Right, A / D", "steer"},
      {"Space", "handbrake; after the run ends: retry"},
      {"Enter", "retry after the run ends (PARKED, TIME UP, GAME OVER)"},
      {"P", "pause / resume"},
      {"N", "step one frame while paused; once parked: next level"},
      {"R", "restart"},
      {"B", "debug overlay (AABB, OBBs, candidates, contacts)"},
      {"+ / -", "zoom in / out"},
      {"[ / ]", "replay speed (0.25x to 8x)"},
      {"M", "sound on / off"},
      {"F11", "full screen"},
      {"F12", "save a PNG screenshot"},
      {"F1", "this help (the game waits)"},
      {"Esc", "back to the level list (when started from it), else quit"},
  };
  return keys;
}

void drawHelp(Canvas& canvas, const std::string& note, const std::string& task) {
  const Eigen::Vector2i vp = canvas.size();
  const float s = hudScale(vp);
  const int h = px(17, s);
  const int title_h = px(22, s);
  const float row = h * 1.45f;
  float key_w = 0.0f;
  float desc_w = 0.0f;
  for (const auto& [k, d] : helpKeys()) {
    key_w = std::max(key_w, canvas.textSize(k, h).x());
    desc_w = std::max(desc_w, canvas.textSize(d, h).x());
  }
  const float gap = 24.0f * s;
  const float pad = 22.0f * s;
  const std::string task_line = task.empty() ? std::string() : "Task: " + task;
  const float task_h = task.empty() ? 0.0f : 2.0f * row;
  const float w = std::max(key_w + gap + desc_w, canvas.textSize(task_line, h).x()) + 2.0f * pad;
  const float hgt =
      title_h * 1.8f + task_h + row * static_cast<float>(helpKeys().size()) + 2.0f * pad;
  const Eigen::Vector2f tl{0.5f * (static_cast<float>(vp.x()) - w),
                           0.5f * (static_cast<float>(vp.y()) - hgt)};
  fillRect(canvas, tl, {w, hgt}, {12, 14, 18, 225});
  canvas.text(tl + Eigen::Vector2f{pad, pad}, "Keys", title_h, kBannerText);
  if (!note.empty()) {
    const float nw = canvas.textSize(note, title_h).x();
    canvas.text({tl.x() + w - pad - nw, tl.y() + pad}, note, title_h, kBannerText);
  }
  float y = tl.y() + pad + title_h * 1.8f;
  if (!task.empty()) {
    canvas.text({tl.x() + pad, y}, task_line, h, kText);
    y += task_h;
  }
  for (const auto& [k, d] : helpKeys()) {
    canvas.text({tl.x() + pad, y}, k, h, kBannerText);
    canvas.text({tl.x() + pad + key_w + gap, y}, d, h, kText);
    y += row;
  }
}

}  // namespace cardemo
