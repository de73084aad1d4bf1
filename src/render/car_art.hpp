#pragma once
/// How a car looks: body, glass, roof lines, lamps, tyres showing the steering, dents and the hit
/// flash; drawn with sprites when the canvas has them, else with vectors.

#include <span>

#include "geometry/obb2.hpp"
#include "render/camera.hpp"
#include "render/canvas.hpp"
#include "render/draw_world.hpp"
#include "render/effects.hpp"

namespace cardemo {

/// The state of one car for drawing.
struct CarLook {
  Rgba body;                          ///< Paint.
  double steer = 0.0;                 ///< Front-wheel angle, radians, positive to the left.
  double wheelbase = 2.7;             ///< Axle distance, metres.
  bool lit = false;                   ///< Headlamps on (the player's car; beams: headlights.hpp).
  bool braking = false;               ///< Brake lamps lit.
  bool reversing = false;             ///< Reversing lamps lit.
  float flash = 0.0f;                 ///< Hit flash, 0..1.
  std::span<const Dent> dents;        ///< Dents of every car; only those of `owner` are drawn.
  std::uint32_t owner = kPlayerDent;  ///< Whose dents to draw.
  double damage = 0.0;                ///< Health lost, 0..1 (the player's scratches).
};

/// Draws a car at `box` (nose along box.axis). With `sprites` and a canvas holding them the body
/// and tyres are images tinted with the paint; the rest is drawn with vectors on top.
void drawCarArt(Canvas& canvas, const Camera& camera, const Obb2& box, const CarLook& look,
                const Palette& palette, bool sprites);

}  // namespace cardemo
