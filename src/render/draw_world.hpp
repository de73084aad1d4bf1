#pragma once
/// Draws a World through a Canvas: ground grid, walls, obstacles, parked cars, the player, the HUD
/// and the debug overlay. The same code draws the window and the headless PNGs.

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "geometry/obb2.hpp"
#include "render/camera.hpp"
#include "render/canvas.hpp"
#include "sim/world.hpp"

namespace cardemo {

class Effects;
struct GoalView;

/// What to draw besides the world itself.
struct DrawOptions {
  /// AABB (green), OBBs (red), candidates, contact normals, MTV arrows and live counters.
  bool debug_overlay = false;
  /// The F1 help panel listing every key.
  bool help = false;
  /// Shows PAUSED (drawBanner; in the help panel's title while the help is shown).
  bool paused = false;
  /// A large one-line message in place of PAUSED (e.g. "YOUR TURN"); empty: none.
  std::string banner;
  /// Frames per second, shown in the HUD with the debug overlay (0 hides it).
  double fps = 0.0;
  /// Shows the frame number in the HUD (as the debug overlay and a replay's playback do): a
  /// driving player sees speed and crashes only.
  bool frame_counter = false;
  /// Replay speed shown in the HUD while playing a replay (0 hides it).
  double playback_speed = 0.0;
  /// The run has ended (GAME OVER, PARKED, TIME UP): the HUD's speed reads "stopped", not the
  /// frozen World's last speed, since nothing drives any more.
  bool run_over = false;
  /// Extra one-line status (e.g. "recording to drive.replay").
  std::string status;
  /// Hit feedback, tyre marks, brake lights and dents to draw (none when null).
  const Effects* effects = nullptr;
  /// Draw cars, wheels and ground with the canvas's sprites when it has them (else vectors).
  bool sprites = false;
  /// Rows of the GAME OVER panel in place of its default ones (a level's run summary).
  std::vector<std::pair<std::string, std::string>> game_over_rows;
  /// Keys line of the GAME OVER panel (the keys that work now); empty: "Enter restart    Esc quit".
  std::string game_over_keys;
  /// A level's goal: its bay outlined on the ground under the cars (drawGoalBay), and the arrow,
  /// timer and PARKED / TIME UP panel (drawGoalOverlay) over the HUD and under the help and the
  /// banner; null: no goal.
  const GoalView* goal = nullptr;
};

/// Obstacles at most this many metres across (their bounding box's longer side) are drawn as
/// posts: painted, so that a bollard or pillar stands out from the kerbs and walls.
inline constexpr double kPostMaxSize = 1.0;

/// Colours of the scene (shared by the window, the PNGs and the render tests).
struct Palette {
  Rgba ground{38, 41, 46};       ///< Asphalt.
  Rgba grid{52, 56, 62};         ///< Ground grid lines.
  Rgba wall{200, 200, 210};      ///< Walls from `bounds`.
  Rgba obstacle{150, 140, 120};  ///< Convex obstacles.
  Rgba post{235, 185, 40};       ///< Obstacles at most kPostMaxSize across: posts, pillars.
  Rgba player{230, 60, 50};      ///< The player's car.
  Rgba windscreen{20, 24, 30};   ///< Windscreens (show a car's heading).
  Rgba outside{22, 24, 27};      ///< Ground beyond the walls (when the scene has bounds).
  /// Parked-car colours; each car gets one, chosen from its id (parkedColor()).
  std::array<Rgba, 10> car_colors{{{70, 110, 170},
                                   {200, 200, 205},
                                   {40, 44, 52},
                                   {150, 30, 40},
                                   {220, 170, 50},
                                   {60, 130, 90},
                                   {120, 125, 135},
                                   {235, 235, 230},
                                   {90, 60, 130},
                                   {45, 85, 110}}};
  Rgba rear_window{28, 32, 40};       ///< Rear windows.
  Rgba roof_line{0, 0, 0, 70};        ///< Roof panel outline (over the body colour).
  Rgba tyre{18, 18, 20};              ///< Tyres.
  Rgba headlight{250, 240, 200};      ///< Headlamps.
  Rgba tail_light{120, 20, 24};       ///< Rear lamps, unlit.
  Rgba brake_light{255, 40, 40};      ///< Rear lamps while braking.
  Rgba reverse_light{245, 245, 255};  ///< Reversing lamps.
  Rgba bay_line{215, 215, 200, 150};  ///< Painted parking-bay lines.
  Rgba paint{225, 225, 210, 200};     ///< Scene markings: lines and lane arrows.
  Rgba goal_bay{90, 230, 120};        ///< The goal bay's frame and its P.
  Rgba kerb_a{225, 200, 60};          ///< Kerb blocks along the walls (alternating).
  Rgba kerb_b{40, 40, 44};            ///< Kerb blocks along the walls (alternating).
  Rgba asphalt_dark{35, 38, 43};      ///< Darker asphalt patches.
  Rgba asphalt_light{41, 44, 49};     ///< Lighter asphalt patches.
  Rgba skid{14, 14, 16};              ///< Tyre marks (alpha set per mark).
  Rgba damage_text{255, 96, 72};      ///< Floating damage numbers.
};

/// The colour of parked car `id`: the same id gets the same colour on every run (FNV-1a of it).
[[nodiscard]] Rgba parkedColor(const std::string& id, const Palette& palette = {});

/// Draws the whole frame: world (with the player drawn at `player_box`, which may be interpolated
/// between two steps), then the HUD, the goal, the end panel, help and banner as `options` asks.
void drawFrame(Canvas& canvas, const World& world, const Camera& camera, const Obb2& player_box,
               const DrawOptions& options, const Palette& palette = {});

/// A camera centred on the player's box, with the zoom given.
[[nodiscard]] Camera followCamera(const Obb2& player_box, double pixels_per_metre,
                                  const Eigen::Vector2i& viewport);

}  // namespace cardemo
