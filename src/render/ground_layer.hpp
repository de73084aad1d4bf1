#pragma once
/// The ground under the cars: asphalt (sprite tiles or vector patches), painted parking-bay lines,
/// the walls with their kerb blocks.

#include <string>

#include "render/camera.hpp"
#include "render/canvas.hpp"
#include "render/draw_world.hpp"
#include "sim/scene.hpp"

namespace cardemo {

/// Asphalt over the lot (or the whole view without walls): tiles of the ground sprite when
/// `sprites` and the canvas has it, else the ground colour with darker and lighter patches placed
/// by a hash of 5 m world cells (so they stay put as the camera moves).
void drawGround(Canvas& canvas, const Camera& camera, const Scene& scene, const Palette& palette,
                bool sprites);

/// A painted bay around each parked car in view: a line along each long side, 2.6 m apart (or
/// wider for a wide car), and one across the end behind it.
void drawBayLines(Canvas& canvas, const Camera& camera, const Scene& scene, const Palette& palette);

/// The scene's painted lines and lane arrows, and its goal bay (a tinted box with a bright frame
/// and a P in the middle; a chain's bays each with its number instead).
void drawMarkings(Canvas& canvas, const Camera& camera, const Scene& scene, const Palette& palette);

/// A goal bay's paint: a tinted box with a bright frame and `mark` in the middle (a level's goal,
/// "P" or its number in a chain of bays, or the bay chain's highlighted bay).
void drawGoalPaint(Canvas& canvas, const Camera& camera, const ParkingBay& bay,
                   const Palette& palette, const std::string& mark = "P");

/// The four walls outside `bounds`, with alternating kerb blocks along their inner edge.
void drawWalls(Canvas& canvas, const Camera& camera, const Aabb2& bounds, const Palette& palette);

}  // namespace cardemo
