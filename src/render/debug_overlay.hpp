#pragma once
/// The debug overlay (B): the player's broad-phase AABB in green, every OBB in red, the broad-phase
/// candidates highlighted, contact normals, minimum-translation arrows and live counters.

#include "render/camera.hpp"
#include "render/canvas.hpp"
#include "sim/world.hpp"

namespace cardemo {

/// Overlay colours (the render tests look for them).
struct OverlayPalette {
  Rgba aabb{60, 220, 90};        ///< The player's broad-phase box.
  Rgba obb{235, 50, 50};         ///< Every oriented box and obstacle outline.
  Rgba candidate{255, 205, 40};  ///< Broad-phase candidates of the last query.
  Rgba normal{80, 200, 255};     ///< Contact normals, player to collider.
  Rgba mtv{255, 120, 230};       ///< Minimum-translation arrows (push-out of the player).
};

/// Factor by which minimum-translation arrows are lengthened so millimetre overlaps show.
inline constexpr double kMtvScale = 25.0;

/// The player's broad-phase box as the world queries it (tight or rotation-proof).
[[nodiscard]] Aabb2 broadPhaseBox(const World& world);

/// Draws the overlay; world shapes in view are drawn over the scene, the counters at the top right.
void drawDebugOverlay(Canvas& canvas, const World& world, const Camera& camera,
                      const OverlayPalette& palette = {});

}  // namespace cardemo
