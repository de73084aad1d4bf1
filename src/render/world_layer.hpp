#pragma once
/// The world-space layer of a frame: ground, bay lines, the goal bay, tyre marks, headlight beams,
/// walls, obstacles, parked cars and the player (the metre grid only with the debug overlay).

#include "geometry/obb2.hpp"
#include "render/camera.hpp"
#include "render/canvas.hpp"
#include "render/draw_world.hpp"
#include "sim/world.hpp"

namespace cardemo {

/// Thickness of the walls drawn outside a scene's `bounds`, metres.
inline constexpr double kWallThicknessM = 0.6;

/// Grid lines every metre (minor) and every 10 m (major), only those in view, placed relative to
/// the camera so they stay exact far from the origin; only inside `clip` (world) when given.
void drawGroundGrid(Canvas& canvas, const Camera& camera, const Palette& palette,
                    const Aabb2* clip = nullptr);

/// Ground, bay lines, markings, the level's goal bay (`options.goal`), tyre marks, the player's
/// headlight beams, walls, obstacles and parked cars in view, then the player at `player_box`;
/// hit flashes, dents and lamps from `options.effects` when set.
void drawWorldLayer(Canvas& canvas, const World& world, const Camera& camera,
                    const Obb2& player_box, const DrawOptions& options, const Palette& palette);

}  // namespace cardemo
