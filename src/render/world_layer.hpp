#pragma once
/// The world-space layer of a frame: ground grid, walls, obstacles, parked cars and the player.

#include "geometry/obb2.hpp"
#include "render/camera.hpp"
#include "render/canvas.hpp"
#include "render/draw_world.hpp"
#include "sim/world.hpp"

namespace cardemo {

/// Grid lines every metre (minor) and every 10 m (major), only those in view, placed relative to
/// the camera so they stay exact far from the origin; only inside `clip` (world) when given.
void drawGroundGrid(Canvas& canvas, const Camera& camera, const Palette& palette,
                    const Aabb2* clip = nullptr);

/// A car body with its windscreen near the front (showing the heading).
void drawCar(Canvas& canvas, const Camera& camera, const Obb2& box, const Rgba& body,
             const Palette& palette);

/// Walls, obstacles and parked cars in view, then the player at `player_box`.
void drawWorldLayer(Canvas& canvas, const World& world, const Camera& camera,
                    const Obb2& player_box, const Palette& palette);

}  // namespace cardemo
