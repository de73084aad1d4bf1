#pragma once
/// Drawing one frame without a window or display, into a PNG file. No SDL in this header, so
/// commands can call it without including SDL.

#include <optional>
#include <string>

#include "render/draw_world.hpp"
#include "sim/world.hpp"

namespace cardemo {

/// What a headless picture looks like.
struct RenderSettings {
  int width = 1280;                       ///< Pixels.
  int height = 720;                       ///< Pixels.
  double pixels_per_metre = 12.0;         ///< Zoom of the follow camera.
  std::optional<Eigen::Vector2d> center;  ///< World point at the middle (default: the player).
  std::optional<Camera> camera;  ///< The whole camera (e.g. from a CameraRig); overrides the above.
  DrawOptions options;           ///< HUD, overlay and status line.
  Palette palette;               ///< Colours.
};

/// Draws `world` (camera on the player unless `center` or `camera` is set) with the same code as
/// the window into a software surface and writes it to `out` as PNG, atomically. With
/// `options.sprites` the sprites are loaded first (SdlCanvas::loadSprites). Needs no display:
/// only SDL2_ttf is initialised. Returns an empty string on success, else one line saying what
/// went wrong.
[[nodiscard]] std::string renderPng(const World& world, const RenderSettings& settings,
                                    const std::string& out);

}  // namespace cardemo
