#pragma once
/// Small drawing helpers shared by the world, HUD and overlay: projected boxes, outlines, arrows,
/// screen rectangles.

#include <array>
#include <span>
#include <utility>

#include "geometry/aabb.hpp"
#include "geometry/obb2.hpp"
#include "render/camera.hpp"
#include "render/canvas.hpp"

namespace cardemo {

/// The box's corners in pixels (counter-clockwise in the world, starting at local (+x, -y)).
[[nodiscard]] std::array<Eigen::Vector2f, 4> projectObb(const Camera& camera, const Obb2& box);

/// The screen rectangle (min and max corners, pixels) around a world box.
[[nodiscard]] std::pair<Eigen::Vector2f, Eigen::Vector2f> screenRect(const Camera& camera,
                                                                     const Obb2& box);

/// The windscreen quad of a car box in pixels: a band across the front half, narrower at the front.
[[nodiscard]] std::array<Eigen::Vector2f, 4> windscreenQuad(const Camera& camera, const Obb2& box);

/// The world rectangle the camera sees (a little margin included).
[[nodiscard]] Aabb2 visibleWorld(const Camera& camera);

/// Closed outline through `points` (pixels).
void outline(Canvas& canvas, std::span<const Eigen::Vector2f> points, float thickness,
             const Rgba& color);

/// Arrow from `from` to `to` (pixels) with a head of `head` pixels.
void arrow(Canvas& canvas, const Eigen::Vector2f& from, const Eigen::Vector2f& to, float thickness,
           float head, const Rgba& color);

/// Axis-aligned filled rectangle in pixels.
void fillRect(Canvas& canvas, const Eigen::Vector2f& top_left, const Eigen::Vector2f& size,
              const Rgba& color);

/// `color` with its RGB scaled by `factor` (0..1 darker, >1 lighter, clamped).
[[nodiscard]] Rgba shade(const Rgba& color, double factor);

}  // namespace cardemo
