#pragma once
/// The player's headlight beams: light on the ground ahead of the car, stopped by the first parked
/// car, obstacle or wall each ray meets, drawn under the cars and walls.

#include "geometry/obb2.hpp"
#include "render/camera.hpp"
#include "render/canvas.hpp"
#include "render/draw_world.hpp"
#include "sim/world.hpp"

namespace cardemo {

/// Length of a beam ahead of the bumper in the open, metres.
inline constexpr double kBeamLengthM = 3.2;

/// Two beams ahead of the car `box` (nose along box.axis), each a fan of slices cut short where
/// its rays meet a parked car, an obstacle or the scene's walls.
void drawHeadlightBeams(Canvas& canvas, const Camera& camera, const World& world, const Obb2& box,
                        const Palette& palette);

}  // namespace cardemo
