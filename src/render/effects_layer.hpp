#pragma once
/// Drawing what Effects observed: tyre marks on the ground, floating damage numbers, the pulse of
/// the health bar.

#include "render/camera.hpp"
#include "render/canvas.hpp"
#include "render/draw_world.hpp"
#include "render/effects.hpp"

namespace cardemo {

/// Tyre marks in view, older ones fainter.
void drawSkidMarks(Canvas& canvas, const Camera& camera, const Effects& effects,
                   const Palette& palette);

/// Damage numbers ("-23") rising from the points of impact and fading.
void drawDamageNumbers(Canvas& canvas, const Camera& camera, const Effects& effects,
                       const Palette& palette);

/// Over the HUD's health bar after a hit: the lost part flashes and the bar's frame glows.
void drawHealthPulse(Canvas& canvas, const World& world, const Effects& effects);

}  // namespace cardemo
