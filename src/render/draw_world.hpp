#pragma once
/// Draws a World through a Canvas: ground grid, walls, obstacles, parked cars, the player, the HUD
/// and the debug overlay. The same code draws the window and the headless PNGs.

#include <string>
#include <utility>
#include <vector>

#include "geometry/obb2.hpp"
#include "render/camera.hpp"
#include "render/canvas.hpp"
#include "sim/world.hpp"

namespace cardemo {

/// What to draw besides the world itself.
struct DrawOptions {
  /// AABB (green), OBBs (red), candidates, contact normals, MTV arrows and live counters.
  bool debug_overlay = false;
  /// The F1 help panel listing every key.
  bool help = false;
  /// Shows PAUSED.
  bool paused = false;
  /// A large one-line message at the top instead of PAUSED (e.g. "YOUR TURN"); empty: none.
  std::string banner;
  /// Frames per second shown in the HUD (0 hides it).
  double fps = 0.0;
  /// Replay speed shown in the HUD while playing a replay (0 hides it).
  double playback_speed = 0.0;
  /// Extra one-line status (e.g. "recording to drive.replay").
  std::string status;
  /// Rows of the GAME OVER panel in place of its default ones (a level's run summary).
  std::vector<std::pair<std::string, std::string>> game_over_rows;
};

/// Colours of the scene (shared by the window, the PNGs and the render tests).
struct Palette {
  Rgba ground{38, 41, 46};       ///< Asphalt.
  Rgba grid{52, 56, 62};         ///< Ground grid lines.
  Rgba wall{200, 200, 210};      ///< Walls from `bounds`.
  Rgba parked{70, 110, 170};     ///< Parked cars.
  Rgba obstacle{150, 140, 120};  ///< Convex obstacles.
  Rgba player{230, 60, 50};      ///< The player's car.
  Rgba windscreen{20, 24, 30};   ///< Windscreens (show a car's heading).
  Rgba outside{22, 24, 27};      ///< Ground beyond the walls (when the scene has bounds).
};

/// Draws the whole frame: world (with the player drawn at `player_box`, which may be interpolated
/// between two steps), then the HUD, help and overlay as `options` asks.
void drawFrame(Canvas& canvas, const World& world, const Camera& camera, const Obb2& player_box,
               const DrawOptions& options, const Palette& palette = {});

/// A camera centred on the player's box, with the zoom given.
[[nodiscard]] Camera followCamera(const Obb2& player_box, double pixels_per_metre,
                                  const Eigen::Vector2i& viewport);

}  // namespace cardemo
