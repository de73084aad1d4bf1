#include "render/hud.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/end_panel.hpp"
#include "render/goal_overlay.hpp"
#include "render/hud_colors.hpp"
#include "render/panel_place.hpp"
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

// R stands out (amber, the reversing lamps' colour); N is dim: nothing drives the car.
Rgba gearColor(Gear gear) {
  switch (gear) {
    case Gear::kReverse:
      return {255, 190, 80, 255};
    case Gear::kNeutral:
      return kDim;
    case Gear::kDrive:
      break;
  }
  return kText;
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

std::string speedText(double speed) {
  const double kmh = speed * 3.6;
  // Below half the last digit it reads 0.0, never "-0.0".
  return std::abs(kmh) < 0.05 ? std::string("0.0 km/h") : format("%.1f km/h", kmh);
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

// Rows of the player's HUD table: gear, speed and crashes (the developer rows come below them).
constexpr int kPlayerRows = 3;

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
  // A little below the player's panel, and below the level's timer at its tallest (which, at
  // every HUD scale, ends above that margin: the strip is the panel's).
  const float top = std::max(panel_top + hudPanelHeight(viewport, kPlayerRows) + 8.0f * s,
                             timerPanelBottom(viewport));
  return {top, static_cast<float>(viewport.y()) - statusLineTop(viewport)};
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
  const Gear gear = world.gear();
  rows.push_back({"Gear", std::string(1, gearLetter(gear)), gearColor(gear)});
  rows.push_back(
      {"Speed", options.run_over ? std::string("stopped") : speedText(world.car().speed), kText});
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

ScreenBox drawBanner(Canvas& canvas, const std::string& text, const PanelRoom& room) {
  if (text.empty()) return {};
  const Eigen::Vector2i vp = canvas.size();
  const float s = hudScale(vp);
  const auto size_at = [&](float scale) {
    const float pad = 14.0f * s * scale;
    return Eigen::Vector2f(canvas.textSize(text, px(34, s * scale)) +
                           Eigen::Vector2f::Constant(2.0f * pad));
  };
  // A third of the way down when that covers neither the car nor the bay: clear of the timer and
  // the HUD panels at the top, and above the car, which the camera keeps near the centre.
  const Eigen::Vector2f natural = size_at(1.0f);
  const Eigen::Vector2f preferred{0.5f * (static_cast<float>(vp.x()) - natural.x()),
                                  static_cast<float>(vp.y()) / 3.0f - 0.5f * natural.y()};
  const ScreenBox area = room.area.isEmpty() ? panelArea(vp) : room.area;
  const PanelSpot spot = placeClear(area, room.avoid, 12.0f * s, size_at, preferred);
  const Eigen::Vector2f box = size_at(spot.scale);
  const float pad = 14.0f * s * spot.scale;
  fillRect(canvas, spot.top_left, box, kBannerBackdrop);
  canvas.text(spot.top_left + Eigen::Vector2f{pad, pad}, text, px(34, s * spot.scale), kBannerText);
  return {spot.top_left, spot.top_left + box};
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
        {"Ended", kWreckedText},
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

namespace {

// The help panel's measurements at a size factor `s`.
struct HelpLayout {
  int h, title_h;
  float row, gap, pad, key_w;
  std::vector<std::string> task_lines;  // the task, wrapped to the width of the keys' table
  Eigen::Vector2f size;
};

// `text` split at spaces into lines at most `width` pixels wide (a longer word keeps its line).
std::vector<std::string> wrapped(Canvas& canvas, const std::string& text, int px_height,
                                 float width) {
  std::vector<std::string> lines;
  std::string line;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find(' ', start);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(start, end - start);
    const std::string longer = line.empty() ? word : line + " " + word;
    if (!line.empty() && canvas.textSize(longer, px_height).x() > width) {
      lines.push_back(line);
      line = word;
    } else {
      line = longer;
    }
    start = end + 1;
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

HelpLayout helpLayout(Canvas& canvas, float s, const std::string& task_line) {
  HelpLayout l{};
  l.h = px(17, s);
  l.title_h = px(22, s);
  l.row = static_cast<float>(l.h) * 1.45f;
  float desc_w = 0.0f;
  for (const auto& [k, d] : helpKeys()) {
    l.key_w = std::max(l.key_w, canvas.textSize(k, l.h).x());
    desc_w = std::max(desc_w, canvas.textSize(d, l.h).x());
  }
  l.gap = 24.0f * s;
  l.pad = 22.0f * s;
  const float table = l.key_w + l.gap + desc_w;
  if (!task_line.empty()) l.task_lines = wrapped(canvas, task_line, l.h, table);
  float w = table;
  for (const std::string& line : l.task_lines) w = std::max(w, canvas.textSize(line, l.h).x());
  const float task_h =
      l.task_lines.empty() ? 0.0f : l.row * (static_cast<float>(l.task_lines.size()) + 1.0f);
  const float hgt = static_cast<float>(l.title_h) * 1.8f + task_h +
                    l.row * static_cast<float>(helpKeys().size()) + 2.0f * l.pad;
  l.size = {w + 2.0f * l.pad, hgt};
  return l;
}

}  // namespace

ScreenBox drawHelp(Canvas& canvas, const std::string& note, const std::string& task,
                   const PanelRoom& room) {
  const Eigen::Vector2i vp = canvas.size();
  const float s = hudScale(vp);
  const std::string task_line = task.empty() ? std::string() : "Task: " + task;
  const auto size_at = [&](float scale) { return helpLayout(canvas, s * scale, task_line).size; };
  // Centred when that covers neither the car nor the bay; else beside them, smaller if need be.
  // The game waits while the help is shown, so it may cover the HUD: the whole window is its room.
  const Eigen::Vector2f natural = size_at(1.0f);
  const Eigen::Vector2f preferred = 0.5f * (vp.cast<float>() - natural);
  const Eigen::Vector2f margin = Eigen::Vector2f::Constant(8.0f * s);
  const ScreenBox area =
      room.area.isEmpty() ? ScreenBox(margin, vp.cast<float>() - margin) : room.area;
  const PanelSpot spot = placeClear(area, room.avoid, 12.0f * s, size_at, preferred);
  const HelpLayout l = helpLayout(canvas, s * spot.scale, task_line);
  const Eigen::Vector2f tl = spot.top_left;
  const float w = l.size.x();
  fillRect(canvas, tl, l.size, {12, 14, 18, 225});
  canvas.text(tl + Eigen::Vector2f{l.pad, l.pad}, "Keys", l.title_h, kBannerText);
  if (!note.empty()) {
    const float nw = canvas.textSize(note, l.title_h).x();
    canvas.text({tl.x() + w - l.pad - nw, tl.y() + l.pad}, note, l.title_h, kBannerText);
  }
  float y = tl.y() + l.pad + static_cast<float>(l.title_h) * 1.8f;
  for (const std::string& line : l.task_lines) {
    canvas.text({tl.x() + l.pad, y}, line, l.h, kText);
    y += l.row;
  }
  if (!l.task_lines.empty()) y += l.row;
  for (const auto& [k, d] : helpKeys()) {
    canvas.text({tl.x() + l.pad, y}, k, l.h, kBannerText);
    canvas.text({tl.x() + l.pad + l.key_w + l.gap, y}, d, l.h, kText);
    y += l.row;
  }
  return {tl, tl + l.size};
}

}  // namespace cardemo
