#pragma once
/// Screen-space overlays: the HUD (health bar, gear, speed, crashes; hits, frame, FPS for
/// developers), the PAUSED banner, the game-over panel and the F1 help panel.

#include <string>
#include <vector>

#include "render/camera.hpp"
#include "render/canvas.hpp"
#include "render/draw_world.hpp"
#include "render/panel_place.hpp"
#include "sim/world.hpp"

namespace cardemo {

/// The HUD's speed: km/h with one decimal, negative when reversing ("-3.2 km/h"; "0.0 km/h" below
/// 0.05 km/h either way).
[[nodiscard]] std::string speedText(double speed);

/// Health bar colour: green when full, through yellow, to red when empty (`fraction` in 0..1).
[[nodiscard]] Rgba healthColor(double fraction);

/// Size factor for HUD text and panels at a viewport height (1 at 720 px).
[[nodiscard]] float hudScale(const Eigen::Vector2i& viewport);

/// Where the HUD draws the health bar in a viewport, pixels.
struct HealthBarRect {
  Eigen::Vector2f top_left;  ///< Top-left corner.
  Eigen::Vector2f size;      ///< Width and height.
};

/// The health bar's place in the HUD panel at the top left (drawHud draws it there).
[[nodiscard]] HealthBarRect healthBarRect(const Eigen::Vector2i& viewport);

/// The top of the status line's panel at the bottom left (drawHud draws it there), pixels.
[[nodiscard]] float statusLineTop(const Eigen::Vector2i& viewport);

/// The strips the HUD covers across a viewport, which the camera keeps the scene out of: at the
/// top, down to a little below the player's HUD panel (lower than the level's timer beside it);
/// at the bottom, from the status line's top.
[[nodiscard]] ViewInsets hudInsets(const Eigen::Vector2i& viewport);

/// The health bar: a dark trough of `size`, filled from the left in proportion to health, with
/// the number written on it.
void drawHealthBar(Canvas& canvas, const Eigen::Vector2f& top_left, const Eigen::Vector2f& size,
                   int health, int max_health);

/// The health bar's "health / max" text, light with a dark shadow (drawHealthBar draws it last).
void drawHealthLabel(Canvas& canvas, const Eigen::Vector2f& top_left, const Eigen::Vector2f& size,
                     int health, int max_health);

/// One row of a two-column table.
struct HudRow {
  std::string label;  ///< Left, e.g. "Speed".
  std::string value;  ///< Right-aligned, e.g. "42 km/h".
  Rgba color;         ///< Colour of both.
};

/// Width a table needs: widest label, a gap, widest value.
[[nodiscard]] float tableWidth(Canvas& canvas, const std::vector<HudRow>& rows, int text_px);

/// Draws rows `width` pixels wide (labels left, values right-aligned); returns the height used.
float drawTable(Canvas& canvas, const Eigen::Vector2f& top_left, float width,
                const std::vector<HudRow>& rows, int text_px);

/// The HUD panel at the top left, the status line and the help hint. Returns the bottom-right
/// corner of the panel, pixels.
Eigen::Vector2f drawHud(Canvas& canvas, const World& world, const DrawOptions& options);

/// A large one-line message (PAUSED, YOUR TURN) on an opaque backdrop, centred across the screen a
/// third of the way down, or, when that would cover a box of `room.avoid` (the car's and the
/// bay's screen boxes), where placeClear() puts it in `room.area`; drawn last, over the HUD and
/// the level's timer.
/// Empty text: nothing. Returns the backdrop's box (empty when nothing was drawn).
ScreenBox drawBanner(Canvas& canvas, const std::string& text, const PanelRoom& room = {});

/// The game-over panel beside the car (never over it): time, what ended the run, crashes and
/// damage, or `summary_rows`
/// when given (a level's run summary), and the keys line `keys` (default "Enter restart    Esc
/// quit").
void drawGameOver(Canvas& canvas, const World& world, const Camera& camera, const Obb2& player_box,
                  const std::vector<std::pair<std::string, std::string>>& summary_rows = {},
                  const std::string& keys = {});

/// Every key and what it does, as the help panel lists them.
[[nodiscard]] const std::vector<std::pair<std::string, std::string>>& helpKeys();

/// The F1 help panel, with `note` (e.g. "PAUSED") at the right of its title row and the level's
/// `task`, when given, above the keys (wrapped to their width): centred, or where placeClear()
/// puts it in `room` clear of its boxes (shrunk when it fits nowhere whole). The game waits while
/// it is shown, so an empty `room.area` means the whole window. Returns the panel's box.
ScreenBox drawHelp(Canvas& canvas, const std::string& note = {}, const std::string& task = {},
                   const PanelRoom& room = {});

}  // namespace cardemo
