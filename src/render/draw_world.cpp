#include "render/draw_world.hpp"

#include "render/debug_overlay.hpp"
#include "render/hud.hpp"
#include "render/world_layer.hpp"

namespace cardemo {

void drawFrame(Canvas& canvas, const World& world, const Camera& camera, const Obb2& player_box,
               const DrawOptions& options, const Palette& palette) {
  canvas.clear(world.scene().bounds ? palette.outside : palette.ground);
  drawWorldLayer(canvas, world, camera, player_box, palette);
  if (options.debug_overlay) drawDebugOverlay(canvas, world, camera);
  drawHud(canvas, world, options);
  if (world.gameOver()) drawGameOver(canvas, world, camera, player_box, options.game_over_rows);
  if (options.help) drawHelp(canvas);
}

Camera followCamera(const Obb2& player_box, double pixels_per_metre,
                    const Eigen::Vector2i& viewport) {
  Camera camera;
  camera.center = player_box.center;
  camera.pixels_per_metre = pixels_per_metre;
  camera.viewport = viewport;
  return camera;
}

}  // namespace cardemo
